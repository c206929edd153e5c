!!ARBfp1.0
# texture target 4D does not exist (ARBfp 3.11.2 <texTarget>)
# FAIL
# EXPECT-ERROR: 5:53 arb-texture-target
TEX result.color, fragment.texcoord[0], texture[0], 4D;
END
