!!ARBfp1.0
# MOV with two source operands (ARBfp 3.11.2 <VECTORop_instruction>)
# FAIL
# EXPECT-ERROR: 6:22 arb-syntax-expected
TEMP t;
MOV t, fragment.color, fragment.color.secondary;
MOV result.color, fragment.color;
END
