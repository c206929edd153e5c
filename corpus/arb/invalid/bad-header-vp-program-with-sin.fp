!!ARBvp1.0
# a !!ARBvp1.0 header makes this a vertex program, where SIN does not exist (ARBvp 2.14.2 <instruction>)
# FAIL
# EXPECT-ERROR: 6:1 arb-syntax-opcode-stage
MOV result.position, vertex.position;
SIN result.color.x, vertex.color.x;
END
