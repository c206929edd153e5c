!!ARBfp1.0
# ARGS: --limits spec-min
# five texture indirections exceed the spec minimum of four
TEMP a;
TEX a, fragment.texcoord[0], texture[0], 2D;
TEX a, a, texture[0], 2D;
TEX a, a, texture[0], 2D;
TEX a, a, texture[0], 2D;
TEX a, a, texture[0], 2D;
MOV result.color, a;
END
