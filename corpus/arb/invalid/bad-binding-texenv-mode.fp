!!ARBfp1.0
# state.texenv[n] has only color (ARBfp 3.11.2 <stateTexEnvProperty>)
# FAIL
# EXPECT-ERROR: 5:51 arb-binding-unknown
MUL result.color, fragment.color, state.texenv[0].mode;
END
