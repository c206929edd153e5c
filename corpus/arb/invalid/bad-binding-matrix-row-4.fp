!!ARBfp1.0
# state.matrix.mvp.row[4]: rows are 0 to 3 (ARBfp 3.11.2 <stateMatrixRowNum>)
# FAIL
# EXPECT-ERROR: 5:32 arb-binding-index-range
PARAM r = state.matrix.mvp.row[4];
MOV result.color, fragment.color;
END
