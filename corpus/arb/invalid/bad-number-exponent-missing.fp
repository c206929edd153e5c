!!ARBfp1.0
# a float constant with e but no exponent digits (ARBfp 3.11.2 <floatConstant>)
# FAIL
# EXPECT-ERROR: 5:35 arb-lex-bad-number
MUL result.color, fragment.color, 2.5e;
END
