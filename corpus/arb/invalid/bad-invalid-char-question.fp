!!ARBfp1.0
# the character ? is not part of any token (ARBfp 3.11.2: undefined characters)
# FAIL
# EXPECT-ERROR: 5:33 arb-lex-invalid-char
MOV result.color, fragment.color?;
END
