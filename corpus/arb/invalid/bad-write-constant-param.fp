!!ARBfp1.0
# a write to a constant PARAM (ARBfp 3.11.3.2: constants can never be modified)
# FAIL
# EXPECT-ERROR: 6:5 arb-operand-dst-readonly
PARAM half = { 0.5, 0.5, 0.5, 1 };
MOV half.x, fragment.color.x;
MOV result.color, fragment.color;
END
