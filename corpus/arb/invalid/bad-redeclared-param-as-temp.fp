!!ARBfp1.0
# a PARAM name declared again as a TEMP (ARBfp 3.11.3)
# FAIL
# EXPECT-ERROR: 6:6 arb-decl-redeclared
PARAM tint = program.local[0];
TEMP tint;
MOV result.color, fragment.color;
END
