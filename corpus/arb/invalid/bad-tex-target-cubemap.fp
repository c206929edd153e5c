!!ARBfp1.0
# texture target CUBEMAP: the name is CUBE (ARBfp 3.11.2 <texTarget>)
# FAIL
# EXPECT-ERROR: 5:53 arb-texture-target
TXP result.color, fragment.texcoord[0], texture[0], CUBEMAP;
END
