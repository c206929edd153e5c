!!ARBfp1.0
# a destination given a swizzle .xxyy instead of a mask (ARBfp 3.11.2 <optionalMask>)
# FAIL
# EXPECT-ERROR: 6:7 arb-operand-mask
TEMP t;
MOV t.xxyy, fragment.color;
MOV result.color, fragment.color;
END
