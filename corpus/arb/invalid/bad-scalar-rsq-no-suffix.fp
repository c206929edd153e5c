!!ARBfp1.0
# RSQ needs a scalar operand: an attribute without suffix (ARBfp 3.11.2 <scalarSrcReg>)
# FAIL
# EXPECT-ERROR: 6:8 arb-operand-scalar
TEMP r;
RSQ r, fragment.texcoord[0];
MOV result.color, fragment.color;
END
