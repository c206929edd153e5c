!!ARBfp1.0
# Five dependent texture reads: five texture indirections.
TEMP a;
TEX a, fragment.texcoord[0], texture[0], 2D;
TEX a, a, texture[0], 2D;
TEX a, a, texture[0], 2D;
TEX a, a, texture[0], 2D;
TEX a, a, texture[0], 2D;
MOV result.color, a;
END
