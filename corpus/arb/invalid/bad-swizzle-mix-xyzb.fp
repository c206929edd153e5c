!!ARBfp1.0
# a source swizzle mixing xyzw and rgba: .xyzb (ARBfp 3.11.2 <optionalSuffix>)
# FAIL
# EXPECT-ERROR: 7:21 arb-operand-swizzle-mix
TEMP t;
MOV t, fragment.texcoord[0];
ADD result.color, t.xyzb, fragment.color;
END
