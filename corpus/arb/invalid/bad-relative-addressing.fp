!!ARBfp1.0
# relative addressing of a parameter array in a fragment program (ARBfp 3.11.2 <progParamArrayAbs>)
# FAIL
# EXPECT-ERROR: 6:23 arb-operand-relative-fp
PARAM arr[] = { program.env[0..3] };
MOV result.color, arr[A0.x + 1];
END
