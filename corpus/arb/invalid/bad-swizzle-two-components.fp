!!ARBfp1.0
# a two-component source swizzle .xy (ARBfp 3.11.2 <optionalSuffix>)
# FAIL
# EXPECT-ERROR: 6:29 arb-operand-swizzle
TEMP t;
MOV t, fragment.texcoord[0].xy;
MOV result.color, fragment.color;
END
