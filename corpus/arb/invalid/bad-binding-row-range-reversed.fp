!!ARBfp1.0
# state.matrix.mvp.row[3..1]: first row after last (ARBfp 3.11.3.2)
# FAIL
# EXPECT-ERROR: 5:42 arb-binding-row-range
PARAM rows[] = { state.matrix.mvp.row[3..1] };
MOV result.color, fragment.color;
END
