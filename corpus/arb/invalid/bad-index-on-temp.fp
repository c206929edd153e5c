!!ARBfp1.0
# an index on a TEMP (ARBfp 3.11.2 <progParamArray>)
# FAIL
# EXPECT-ERROR: 7:20 arb-operand-not-array
TEMP t;
MOV t, fragment.color;
MOV result.color, t[1];
END
