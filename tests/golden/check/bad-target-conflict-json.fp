!!ARBfp1.0
# ARGS: --format json
TEMP t;
TEX t, fragment.texcoord[0], texture[0], 2D;
TEX t, fragment.texcoord[0], texture[0], CUBE;
MOV result.color, t;
END
