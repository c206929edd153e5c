!!ARBfp1.0
# EX2 needs a scalar operand: a parameter without suffix (ARBfp 3.11.2 <scalarSrcReg>)
# FAIL
# EXPECT-ERROR: 7:8 arb-operand-scalar
PARAM k = program.local[0];
TEMP r;
EX2 r, k;
MOV result.color, fragment.color;
END
