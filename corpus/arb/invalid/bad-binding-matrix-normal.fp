!!ARBfp1.0
# state.matrix.normal does not exist (ARBfp 3.11.2 <stateMatrixName>)
# FAIL
# EXPECT-ERROR: 5:25 arb-binding-unknown
PARAM r0 = state.matrix.normal.row[0];
MOV result.color, fragment.color;
END
