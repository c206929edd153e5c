!!ARBfp1.0
# an empty constant vector {} (ARBfp 3.11.2 <paramConstVector>)
# FAIL
# EXPECT-ERROR: 5:13 arb-syntax-expected
PARAM k = { };
MOV result.color, fragment.color;
END
