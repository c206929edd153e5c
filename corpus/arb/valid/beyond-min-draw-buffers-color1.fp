!!ARBfp1.0
# result.color[1] with ARB_draw_buffers: beyond the minimum MAX_DRAW_BUFFERS_ARB of 1 (ARB_draw_buffers)
# no warning by default (Mesa takes it); --limits spec-min rejects it
OPTION ARB_draw_buffers;
TEMP base;
TEX base, fragment.texcoord[0], texture[0], 2D;
MOV result.color[0], base;
MUL result.color[1], base, fragment.color;
END
