!!ARBfp1.0
# opcodes are case-sensitive: mov is not an instruction (ARBfp 3.11.2)
# FAIL
# EXPECT-ERROR: 5:1 arb-syntax-unknown-instruction
mov result.color, fragment.color;
END
