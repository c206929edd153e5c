!!ARBfp1.0
# a float constant whose exponent is only a sign (ARBfp 3.11.2 <floatConstant>)
# FAIL
# EXPECT-ERROR: 5:13 arb-lex-bad-number
PARAM k = { 1e+, 0, 0, 1 };
MOV result.color, fragment.color;
END
