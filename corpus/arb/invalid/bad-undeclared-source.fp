!!ARBfp1.0
# an undeclared name as a source operand (ARBfp 3.11.3)
# FAIL
# EXPECT-ERROR: 5:35 arb-decl-undeclared
MUL result.color, fragment.color, tint;
END
