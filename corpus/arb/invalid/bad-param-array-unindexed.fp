!!ARBfp1.0
# a PARAM array used without an index (ARBfp 3.11.2 <progParamReg>)
# FAIL
# EXPECT-ERROR: 6:35 arb-operand-array-unindexed
PARAM pal[] = { program.env[0..3] };
MUL result.color, fragment.color, pal;
END
