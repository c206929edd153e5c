!!ARBfp1.0
# the program ends without END (ARBfp 3.11.2 <program>)
# FAIL
# EXPECT-ERROR: 7:40 arb-syntax-missing-end
TEMP base;
TEX base, fragment.texcoord[0], texture[0], 2D;
MUL result.color, base, fragment.color;