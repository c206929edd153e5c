!!ARBfp1.0
# a write to fragment.color (ARBfp 3.11.3.1: attributes are read-only)
# FAIL
# EXPECT-ERROR: 5:5 arb-operand-dst-readonly
MOV fragment.color, fragment.color.secondary;
MOV result.color, fragment.color;
END
