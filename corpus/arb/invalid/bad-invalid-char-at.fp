!!ARBfp1.0
# the character @ is not part of any token (ARBfp 3.11.2: undefined characters)
# FAIL
# EXPECT-ERROR: 7:25 arb-lex-invalid-char
TEMP base;
TEX base, fragment.texcoord[0], texture[0], 2D;
MUL result.color, base, @fragment.color;
END
