!!ARBfp1.0
# SCS needs a scalar operand (ARBfp 3.11.2 <scalarSrcReg>)
# FAIL
# EXPECT-ERROR: 6:11 arb-operand-scalar
TEMP r;
SCS r.xy, program.local[0];
MOV result.color, fragment.color;
END
