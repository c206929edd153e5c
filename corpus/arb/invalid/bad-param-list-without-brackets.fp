!!ARBfp1.0
# a list of bindings given to a single PARAM (ARBfp 3.11.2 <PARAM_singleStmt>)
# FAIL
# EXPECT-ERROR: 5:13 arb-syntax-expected
PARAM k = { { 1, 0, 0, 1 }, { 0, 1, 0, 1 } };
MOV result.color, fragment.color;
END
