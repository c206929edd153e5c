!!ARBfp1.0
# a write to a PARAM (ARBfp 3.11.3.2: parameters are read-only)
# FAIL
# EXPECT-ERROR: 6:5 arb-operand-dst-readonly
PARAM tint = program.local[0];
MUL tint, tint, fragment.color;
MOV result.color, fragment.color;
END
