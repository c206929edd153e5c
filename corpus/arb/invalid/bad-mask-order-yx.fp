!!ARBfp1.0
# a write mask out of xyzw order: .yx (ARBfp 3.11.2 <xyzwMask>)
# FAIL
# EXPECT-ERROR: 7:7 arb-operand-mask
TEMP t;
MOV t, fragment.color;
MOV t.yx, fragment.texcoord[0];
MOV result.color, t;
END
