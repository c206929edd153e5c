!!ARBfp1.0
# COS needs a scalar operand (ARBfp 3.11.2 <scalarSrcReg>)
# FAIL
# EXPECT-ERROR: 6:8 arb-operand-scalar
TEMP r;
COS r, fragment.texcoord[0];
MOV result.color, fragment.color;
END
