!!ARBfp1.0
# an index on a single PARAM (ARBfp 3.11.2 <progParamArray>)
# FAIL
# EXPECT-ERROR: 6:39 arb-operand-not-array
PARAM tint = program.local[0];
MUL result.color, fragment.color, tint[0];
END
