!!ARBfp1.0
# a constant vector with five components (ARBfp 3.11.2 <paramConstVector>)
# FAIL
# EXPECT-ERROR: 5:25 arb-param-components
PARAM k = { 1, 2, 3, 4, 5 };
MOV result.color, fragment.color;
END
