!!ARBfp1.0
# MOV_SAT_SAT is not an instruction (ARBfp 3.11.2 <VECTORop>)
# FAIL
# EXPECT-ERROR: 5:1 arb-syntax-unknown-instruction
MOV_SAT_SAT result.color, fragment.color;
END
