!!ARBfp1.0
# five texture indirections: beyond the minimum of 4, accepted by Mesa (ARBfp 3.11.3.6, 3.11.6)
# no warning by default (Mesa takes it); --limits spec-min rejects it
# A five-deep dependent chain; each TEX reads the temporary the previous one wrote.
TEMP a, b, c;
TEX a, fragment.texcoord[0], texture[0], 2D;      # indirection 1
TEX b, a, texture[1], 2D;                         # 2
TEX c, b, texture[0], 2D;                         # 3
TEX c, c, texture[1], 2D;                         # 4
TEX c, c, texture[0], 2D;                         # 5
MUL result.color, c, fragment.color;
END
