!!ARBfp1.0
# texture is a reserved word: not a TEMP name (ARBfp 3.11.2 <identifier>)
# FAIL
# EXPECT-ERROR: 5:6 arb-syntax-reserved-name
TEMP texture;
MOV result.color, fragment.color;
END
