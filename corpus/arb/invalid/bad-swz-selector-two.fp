!!ARBfp1.0
# SWZ selector 2: only 0, 1 or a component (ARBfp 3.11.2 <xyzwExtSwizSel>)
# FAIL
# EXPECT-ERROR: 6:30 arb-operand-extended-swizzle
TEMP t;
SWZ t, fragment.color, x, y, 2, w;
MOV result.color, fragment.color;
END
