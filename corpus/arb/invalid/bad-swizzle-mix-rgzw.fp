!!ARBfp1.0
# a source swizzle mixing rgba and xyzw: .rgzw (ARBfp 3.11.2 <optionalSuffix>)
# FAIL
# EXPECT-ERROR: 5:34 arb-operand-swizzle-mix
MOV result.color, fragment.color.rgzw;
END
