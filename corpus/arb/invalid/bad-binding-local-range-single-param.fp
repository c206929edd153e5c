!!ARBfp1.0
# a parameter range bound to a single PARAM (ARBfp 3.11.2 <paramSingleItemDecl>)
# FAIL
# EXPECT-ERROR: 5:11 arb-param-array-item
PARAM p = program.local[0..3];
MOV result.color, fragment.color;
END
