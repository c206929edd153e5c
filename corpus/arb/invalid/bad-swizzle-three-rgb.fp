!!ARBfp1.0
# a three-component rgba source swizzle .rgb (ARBfp 3.11.2 <optionalSuffix>)
# FAIL
# EXPECT-ERROR: 5:34 arb-operand-swizzle
MUL result.color, fragment.color.rgb, program.local[0];
END
