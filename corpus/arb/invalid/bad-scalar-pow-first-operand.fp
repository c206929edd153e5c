!!ARBfp1.0
# POW needs two scalar operands: the base has an rgba swizzle of four (ARBfp 3.11.2 <BINSCop_instruction>)
# FAIL
# EXPECT-ERROR: 6:23 arb-operand-scalar
TEMP r;
POW r, fragment.color.rrrr, program.local[0].x;
MOV result.color, fragment.color;
END
