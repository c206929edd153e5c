!!ARBfp1.0
# a ! outside the header is not part of any token (ARBfp 3.11.2: undefined characters)
# FAIL
# EXPECT-ERROR: 7:19 arb-lex-invalid-char
TEMP c;
MOV c, fragment.color;
MOV result.color, !c;
END
