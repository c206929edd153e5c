!!ARBfp1.0
# fog, precision, shadow and draw-buffers options in one program (ARBfp 3.11.4.5, ARB_fragment_program_shadow, ARB_draw_buffers)
OPTION ARB_fog_linear;
OPTION ARB_precision_hint_nicest;
OPTION ARB_fragment_program_shadow;
OPTION ARB_draw_buffers;
TEMP lit;
TEX lit, fragment.texcoord[1], texture[1], SHADOW2D;
MUL result.color[0], fragment.color, lit.x;
END
