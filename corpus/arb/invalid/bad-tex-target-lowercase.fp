!!ARBfp1.0
# texture targets are upper case: 2d is unknown (ARBfp 3.11.2 <texTarget>)
# FAIL
# EXPECT-ERROR: 5:53 arb-texture-target
TEX result.color, fragment.texcoord[0], texture[0], 2d;
END
