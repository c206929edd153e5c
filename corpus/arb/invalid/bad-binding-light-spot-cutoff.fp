!!ARBfp1.0
# state.light[n].spot takes only direction (ARBfp 3.11.2 <stateSpotProperty>)
# FAIL
# EXPECT-ERROR: 5:55 arb-binding-unknown
MUL result.color, fragment.color, state.light[0].spot.cutoff;
END
