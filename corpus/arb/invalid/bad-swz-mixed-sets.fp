!!ARBfp1.0
# SWZ selectors mixing xyzw and rgba (ARBfp 3.11.2 <extendedSwizzle>)
# FAIL
# EXPECT-ERROR: 6:27 arb-operand-swizzle-mix
TEMP t;
SWZ t, fragment.color, x, g, z, 1;
MOV result.color, fragment.color;
END
