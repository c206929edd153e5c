!!ARBfp1.0
# state.material.glossiness does not exist (ARBfp 3.11.2 <stateMatProperty>)
# FAIL
# EXPECT-ERROR: 5:26 arb-binding-unknown
PARAM g = state.material.glossiness;
MOV result.color, fragment.color;
END
