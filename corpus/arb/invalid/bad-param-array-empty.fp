!!ARBfp1.0
# a PARAM array with an empty initializer list (ARBfp 3.11.2 <paramMultInitList>)
# FAIL
# EXPECT-ERROR: 5:17 arb-syntax-expected
PARAM arr[] = { };
MOV result.color, fragment.color;
END
