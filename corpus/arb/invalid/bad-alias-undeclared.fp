!!ARBfp1.0
# an ALIAS of an undeclared name (ARBfp 3.11.3.5)
# FAIL
# EXPECT-ERROR: 6:11 arb-decl-alias-undeclared
TEMP a;
ALIAS b = c;
MOV result.color, fragment.color;
END
