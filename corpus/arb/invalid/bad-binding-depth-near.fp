!!ARBfp1.0
# state.depth.near does not exist: use state.depth.range (ARBfp 3.11.2 <stateDepthProperty>)
# FAIL
# EXPECT-ERROR: 5:47 arb-binding-unknown
MUL result.color, fragment.color, state.depth.near;
END
