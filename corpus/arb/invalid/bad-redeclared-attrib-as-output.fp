!!ARBfp1.0
# an ATTRIB name declared again as an OUTPUT (ARBfp 3.11.3)
# FAIL
# EXPECT-ERROR: 6:8 arb-decl-redeclared
ATTRIB col = fragment.color;
OUTPUT col = result.color;
MOV result.color, col;
END
