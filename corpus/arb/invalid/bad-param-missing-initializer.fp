!!ARBfp1.0
# PARAM without = and a binding (ARBfp 3.11.2 <PARAM_singleStmt>)
# FAIL
# EXPECT-ERROR: 5:11 arb-syntax-expected
PARAM tint;
MOV result.color, fragment.color;
END
