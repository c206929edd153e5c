!!ARBfp1.0
# fragment.normal does not exist (ARBfp 3.11.3.1, Table X.1)
# FAIL
# EXPECT-ERROR: 5:28 arb-binding-unknown
MOV result.color, fragment.normal;
END
