!!ARBfp1.0
# the write mask .rgw from the spec example: names from both sets (ARBfp 3.11.4.3)
# FAIL
# EXPECT-ERROR: 5:18 arb-operand-swizzle-mix
MOV result.color.rgw, fragment.color;
END
