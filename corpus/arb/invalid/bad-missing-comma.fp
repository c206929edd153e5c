!!ARBfp1.0
# operands not separated by a comma (ARBfp 3.11.2 <BINop_instruction>)
# FAIL
# EXPECT-ERROR: 6:7 arb-syntax-expected
TEMP t;
ADD t fragment.color, fragment.color.secondary;
MOV result.color, fragment.color;
END
