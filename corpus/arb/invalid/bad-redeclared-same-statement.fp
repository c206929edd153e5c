!!ARBfp1.0
# a name repeated in one TEMP list (ARBfp 3.11.3)
# FAIL
# EXPECT-ERROR: 5:12 arb-decl-redeclared
TEMP a, b, a;
MOV result.color, fragment.color;
END
