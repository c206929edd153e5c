!!ARBfp1.0
# KIL takes one operand (ARBfp 3.11.2 <KIL_instruction>)
# FAIL
# EXPECT-ERROR: 5:25 arb-syntax-expected
KIL fragment.texcoord[0], fragment.texcoord[1];
MOV result.color, fragment.color;
END
