!!ARBfp1.0
# a dependent texture chain of exactly four indirections (ARBfp 3.11.6, issue 24)
# Environment-mapped bump mapping, twice perturbed.
TEMP a, b, c;
TEX a, fragment.texcoord[0], texture[0], 2D;      # indirection 1
TEX b, a, texture[1], 2D;                         # 2: a was written in this node
TEX c, b, texture[0], 2D;                         # 3
TEX c, c, texture[1], 2D;                         # 4
MUL result.color, c, fragment.color;
END
