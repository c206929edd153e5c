!!ARBfp1.0
# an instruction not terminated by ; (ARBfp 3.11.2 <statement>)
# FAIL
# EXPECT-ERROR: 6:47 arb-syntax-missing-semicolon
TEMP base;
TEX base, fragment.texcoord[0], texture[0], 2D
MUL result.color, base, fragment.color;
END
