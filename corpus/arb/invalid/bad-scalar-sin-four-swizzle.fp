!!ARBfp1.0
# SIN with a four-component swizzle (ARBfp 3.11.2 <scalarSuffix>)
# FAIL
# EXPECT-ERROR: 6:25 arb-operand-scalar
TEMP r;
SIN r, program.local[0].wwww;
MOV result.color, fragment.color;
END
