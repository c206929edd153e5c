!!ARBfp1.0
# state.point is a vertex program binding (ARBfp 3.11.2 <stateSingleItem>)
# FAIL
# EXPECT-ERROR: 5:41 arb-binding-stage
MUL result.color, fragment.color, state.point.size;
END
