!!ARBfp1.0
# the spec example: 2D then 3D on texture[0] (ARBfp 3.11.6)
# FAIL
# EXPECT-ERROR: 6:53 arb-texture-target-conflict
TEX result.color, fragment.texcoord[0], texture[0], 2D;
TEX result.depth, fragment.texcoord[1], texture[0], 3D;
END
