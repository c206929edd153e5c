!!ARBfp1.0
# a write to an ATTRIB name (ARBfp 3.11.2 <dstReg>)
# FAIL
# EXPECT-ERROR: 6:5 arb-operand-dst-readonly
ATTRIB uv = fragment.texcoord[0];
MUL uv, uv, 2.0;
TEX result.color, uv, texture[0], 2D;
END
