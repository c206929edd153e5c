!!ARBfp1.0
# ADD with one source operand (ARBfp 3.11.2 <BINop_instruction>)
# FAIL
# EXPECT-ERROR: 6:22 arb-syntax-expected
TEMP t;
ADD t, fragment.color;
MOV result.color, fragment.color;
END
