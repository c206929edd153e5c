!!ARBfp1.0
# a TEMP declared twice (ARBfp 3.11.3: each name once)
# FAIL
# EXPECT-ERROR: 6:6 arb-decl-redeclared
TEMP base;
TEMP base;
MOV result.color, fragment.color;
END
