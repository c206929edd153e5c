!!ARBfp1.0
# SHADOW2D target with OPTION ARB_fragment_program_shadow (ARB_fragment_program_shadow)
OPTION ARB_fragment_program_shadow;
TEMP lit;
TEX lit, fragment.texcoord[1], texture[1], SHADOW2D;
MUL result.color, fragment.color, lit.x;
END
