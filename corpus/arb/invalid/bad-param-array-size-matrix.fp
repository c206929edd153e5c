!!ARBfp1.0
# PARAM array size 3 bound to a whole matrix (four rows) (ARBfp 3.11.3.2)
# FAIL
# EXPECT-ERROR: 5:9 arb-param-array-size
PARAM m[3] = { state.matrix.mvp };
MOV result.color, fragment.color;
END
