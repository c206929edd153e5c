!!ARBfp1.0
# PARAM array size 3 with two bindings (ARBfp 3.11.3.2: sizes must match)
# FAIL
# EXPECT-ERROR: 5:9 arb-param-array-size
PARAM k[3] = { { 1, 0, 0, 1 }, { 0, 1, 0, 1 } };
MOV result.color, fragment.color;
END
