!!ARBfp1.0
# state.light[8]: beyond MAX_LIGHTS (8) (ARBfp 3.11.2 <stateLightNumber>)
# FAIL
# EXPECT-ERROR: 5:47 arb-binding-index-range
MUL result.color, fragment.color, state.light[8].diffuse;
END
