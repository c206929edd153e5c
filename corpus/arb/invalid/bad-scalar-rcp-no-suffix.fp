!!ARBfp1.0
# RCP needs a scalar operand: no component suffix (ARBfp 3.11.2 <scalarSrcReg>)
# FAIL
# EXPECT-ERROR: 7:8 arb-operand-scalar
TEMP t, r;
MOV t, fragment.texcoord[0];
RCP r, t;
MOV result.color, fragment.color;
END
