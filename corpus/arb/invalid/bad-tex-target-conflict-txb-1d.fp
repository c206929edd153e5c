!!ARBfp1.0
# texture[1] as 3D by TXP, then as 1D by TXB (ARBfp 3.11.6)
# FAIL
# EXPECT-ERROR: 7:42 arb-texture-target-conflict
TEMP a, b;
TXP a, fragment.texcoord[1], texture[1], 3D;
TXB b, fragment.texcoord[1], texture[1], 1D;
MUL result.color, a, fragment.color;
END
