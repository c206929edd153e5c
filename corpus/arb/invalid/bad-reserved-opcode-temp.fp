!!ARBfp1.0
# an opcode (MUL_SAT) is a reserved word: not a TEMP name (ARBfp 3.11.2 <identifier>)
# FAIL
# EXPECT-ERROR: 5:6 arb-syntax-reserved-name
TEMP MUL_SAT;
MOV result.color, fragment.color;
END
