!!ARBfp1.0
# ATI_draw_buffers: ATI's spelling of the ARB_draw_buffers option; result.color[n] writes draw buffer n (ATI_draw_buffers)
OPTION ATI_draw_buffers;
TEMP base;
TEX base, fragment.texcoord[0], texture[0], 2D;
MOV result.color[0], base;
MUL result.color[1], base, fragment.color;
MOV result.color[2], fragment.texcoord[1];
END
