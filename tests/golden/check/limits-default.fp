!!ARBfp1.0
# three texture coordinate sets and five texture indirections, past the spec minimums (2, 4):
# the default (Mesa's limits) says nothing
TEMP t, u;
TEX t, fragment.texcoord[0], texture[0], 2D;
TEX t, t, texture[0], 2D;
TEX t, t, texture[1], 2D;
TEX t, t, texture[1], 2D;
ADD u, t, fragment.texcoord[2];
TEX t, u, texture[2], 2D;
MUL result.color, t, fragment.texcoord[1];
END
