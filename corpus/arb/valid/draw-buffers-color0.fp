!!ARBfp1.0
# OPTION ARB_draw_buffers with result.color[0] and plain result.color (ARB_draw_buffers)
OPTION ARB_draw_buffers;
OUTPUT out0 = result.color[0];
TEMP base;
TEX base, fragment.texcoord[0], texture[0], 2D;
MUL out0.rgb, base, fragment.color;
MOV result.color[0].a, base.a;
END
