!!ARBfp1.0
# the program ends in a comment without END (ARBfp 3.11.2 <program>)
# FAIL
# EXPECT-ERROR: 6:17 arb-syntax-missing-end
MOV result.color, fragment.color;
# END is missing