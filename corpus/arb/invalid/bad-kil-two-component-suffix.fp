!!ARBfp1.0
# KIL with a mask-like two-component suffix .xy (ARBfp 3.11.2 <KIL_instruction> <vectorSrcReg>)
# FAIL
# EXPECT-ERROR: 5:26 arb-operand-swizzle
KIL fragment.texcoord[0].xy;
MOV result.color, fragment.color;
END
