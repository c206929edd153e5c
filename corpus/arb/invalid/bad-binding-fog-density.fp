!!ARBfp1.0
# state.fog.density does not exist: density is state.fog.params.x (ARBfp 3.11.2 <stateFogProperty>)
# FAIL
# EXPECT-ERROR: 5:45 arb-binding-unknown
MUL result.color, fragment.color, state.fog.density;
END
