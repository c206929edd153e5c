!!ARBfp1.0
# an undeclared name as the destination (ARBfp 3.11.3)
# FAIL
# EXPECT-ERROR: 5:5 arb-decl-undeclared
MOV work, fragment.color;
MOV result.color, fragment.color;
END
