!!ARBfp1.0
# ARB_draw_buffers with exp2 fog: every result.color[n] is fogged, result.depth is not.
OPTION ARB_draw_buffers;
OPTION ARB_fog_exp2;
OPTION ARB_precision_hint_nicest;
TEMP c;
TEX c, fragment.texcoord[0], texture[0], 2D;
MUL result.color[0], c, fragment.color;
MOV result.color[1], fragment.texcoord[0];
MOV_SAT result.color[2].xyz, -c;
MOV result.depth.z, fragment.position.z;
END
