!!ARBfp1.0
# a three-component source swizzle .xyz (ARBfp 3.11.2 <optionalSuffix>)
# FAIL
# EXPECT-ERROR: 6:29 arb-operand-swizzle
TEMP n;
DP3 n, fragment.texcoord[0].xyz, fragment.texcoord[1];
MOV result.color, fragment.color;
END
