!!ARBfp1.0
# PARAM array size 0: sizes run from 1 (ARBfp 3.11.2 <optArraySize>)
# FAIL
# EXPECT-ERROR: 5:9 arb-param-array-size
PARAM k[0] = { { 1, 0, 0, 1 } };
MOV result.color, fragment.color;
END
