!!ARBfp1.0
# KIL has no _SAT form (ARBfp 3.11.2 <KIL_instruction>)
# FAIL
# EXPECT-ERROR: 5:1 arb-syntax-unknown-instruction
KIL_SAT fragment.texcoord[0];
MOV result.color, fragment.color;
END
