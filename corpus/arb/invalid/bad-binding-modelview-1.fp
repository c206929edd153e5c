!!ARBfp1.0
# state.matrix.modelview[1] needs ARB_vertex_blend, which Mesa lacks (ARBfp 3.11.2 <stateModMatNum>)
# FAIL
# EXPECT-ERROR: 5:34 arb-binding-unsupported
PARAM r = state.matrix.modelview[1].row[0];
MOV result.color, fragment.color;
END
