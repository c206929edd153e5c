!!ARBfp1.0
# TEX writing into fragment.texcoord (ARBfp 3.11.2 <maskedDstReg>)
# FAIL
# EXPECT-ERROR: 5:5 arb-operand-dst-readonly
TEX fragment.texcoord[1], fragment.texcoord[0], texture[0], 2D;
MOV result.color, fragment.color;
END
