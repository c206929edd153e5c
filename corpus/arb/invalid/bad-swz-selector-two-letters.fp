!!ARBfp1.0
# SWZ selector xy: each selector is one component (ARBfp 3.11.2 <extendedSwizzle>)
# FAIL
# EXPECT-ERROR: 6:24 arb-operand-extended-swizzle
TEMP t;
SWZ t, fragment.color, xy, z, w, 1;
MOV result.color, fragment.color;
END
