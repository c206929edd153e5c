!!ARBfp1.0
# a write to a state binding (ARBfp 3.11.2 <dstReg>)
# FAIL
# EXPECT-ERROR: 5:5 arb-operand-dst-readonly
MOV state.fog.color, fragment.color;
MOV result.color, fragment.color;
END
