!!ARBfp1.0
# a sign on the destination register (ARBfp 3.11.2 <maskedDstReg>)
# FAIL
# EXPECT-ERROR: 5:5 arb-syntax-expected
MOV -result.color, fragment.color;
END
