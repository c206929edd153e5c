!!ARBfp1.0
# vertex.position is a vertex program binding (ARBfp 3.11.2 <fragAttribBinding>)
# FAIL
# EXPECT-ERROR: 5:19 arb-binding-stage
MOV result.color, vertex.position;
END
