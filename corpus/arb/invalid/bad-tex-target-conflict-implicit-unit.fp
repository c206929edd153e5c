!!ARBfp1.0
# texture (unit 0) as 2D, then texture[0] as RECT (ARBfp 3.11.6)
# FAIL
# EXPECT-ERROR: 7:42 arb-texture-target-conflict
TEMP a, b;
TEX a, fragment.texcoord[0], texture, 2D;
TXP b, fragment.texcoord[1], texture[0], RECT;
MUL result.color, a, fragment.color;
END
