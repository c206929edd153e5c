!!ARBfp1.0
# LG2 with a four-component swizzle instead of one component (ARBfp 3.11.2 <scalarSuffix>)
# FAIL
# EXPECT-ERROR: 6:29 arb-operand-scalar
TEMP r;
LG2 r, fragment.texcoord[0].xxxx;
MOV result.color, fragment.color;
END
