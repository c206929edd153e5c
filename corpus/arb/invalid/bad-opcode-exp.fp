!!ARBfp1.0
# EXP is a vertex program instruction (ARBfp 3.11.2 <instruction>)
# FAIL
# EXPECT-ERROR: 6:1 arb-syntax-opcode-stage
TEMP t;
EXP t, fragment.texcoord[0].x;
MOV result.color, fragment.color;
END
