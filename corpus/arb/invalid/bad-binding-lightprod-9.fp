!!ARBfp1.0
# state.lightprod[9]: beyond MAX_LIGHTS (8) (ARBfp 3.11.2 <stateLightNumber>)
# FAIL
# EXPECT-ERROR: 5:28 arb-binding-index-range
PARAM lp = state.lightprod[9].front.diffuse;
MOV result.color, fragment.color;
END
