!!ARBfp1.0
# ARGS: --no-comments
TEMP c;
TEX c, fragment.texcoord[0], texture[0], 2D;
CMP c, c.x, -c, c;
KIL c;
MOV result.color, c;
END
