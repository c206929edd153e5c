!!ARBfp1.0
# a whole matrix bound to a single PARAM (ARBfp 3.11.2 <paramSingleItemDecl>)
# FAIL
# EXPECT-ERROR: 5:11 arb-binding-matrix-rows
PARAM m = state.matrix.mvp;
MOV result.color, fragment.color;
END
