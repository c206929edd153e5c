!!ARBfp1.0
# a write mask mixing xyzw and rgba: .xg (ARBfp 3.11.4.3)
# FAIL
# EXPECT-ERROR: 7:7 arb-operand-swizzle-mix
TEMP t;
MOV t, fragment.color;
MOV t.xg, fragment.texcoord[0];
MOV result.color, t;
END
