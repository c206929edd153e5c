!!ARBfp1.0
# a two-component swizzle on a TEX coordinate (ARBfp 3.11.2 <vectorSrcReg>)
# FAIL
# EXPECT-ERROR: 5:40 arb-operand-swizzle
TEX result.color, fragment.texcoord[0].xy, texture[0], 2D;
END
