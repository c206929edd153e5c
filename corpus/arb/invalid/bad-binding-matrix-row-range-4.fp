!!ARBfp1.0
# state.matrix.projection.row[2..4]: the range ends past row 3 (ARBfp 3.11.2 <stateMatrixRowNum>)
# FAIL
# EXPECT-ERROR: 5:49 arb-binding-index-range
PARAM rows[] = { state.matrix.projection.row[2..4] };
MOV result.color, fragment.color;
END
