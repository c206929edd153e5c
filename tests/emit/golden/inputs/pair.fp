!!ARBfp1.0
# The fragment half of a pair: reads texcoord[0], texcoord[2] and the fog coordinate.
OPTION ARB_fog_linear;
TEMP t;
TEX t, fragment.texcoord[0], texture[0], 2D;
MAD t, t, fragment.texcoord[2], fragment.color;
MOV result.color, t;
END
