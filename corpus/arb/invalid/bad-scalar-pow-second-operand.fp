!!ARBfp1.0
# POW needs two scalar operands: the exponent has no suffix (ARBfp 3.11.2 <BINSCop_instruction>)
# FAIL
# EXPECT-ERROR: 6:32 arb-operand-scalar
TEMP r;
POW r, fragment.texcoord[0].x, program.local[0];
MOV result.color, fragment.color;
END
