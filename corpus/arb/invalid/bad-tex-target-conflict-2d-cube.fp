!!ARBfp1.0
# one texture unit used with 2D and then CUBE (ARBfp 3.11.6)
# FAIL
# EXPECT-ERROR: 7:42 arb-texture-target-conflict
TEMP a, b;
TEX a, fragment.texcoord[0], texture[0], 2D;
TEX b, fragment.texcoord[1], texture[0], CUBE;
MUL result.color, a, fragment.color;
END
