!!ARBfp1.0
# state is a reserved word: not a PARAM name (ARBfp 3.11.2 <identifier>)
# FAIL
# EXPECT-ERROR: 5:7 arb-syntax-reserved-name
PARAM state = { 1, 1, 1, 1 };
MOV result.color, fragment.color;
END
