!!ARBfp1.0
# ARB_position_invariant is a vertex program option (ARBvp 2.14.4.5.1, ARBfp 3.11.4.5)
# FAIL
# EXPECT-ERROR: 5:8 arb-option-stage
OPTION ARB_position_invariant;
MOV result.color, fragment.color;
END
