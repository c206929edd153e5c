!!ARBfp1.0
# state.texenv[8]: beyond MAX_TEXTURE_UNITS (8 on Mesa) (ARBfp 3.11.2 <legacyTexUnitNum>)
# FAIL
# EXPECT-ERROR: 5:48 arb-binding-index-range
MUL result.color, fragment.color, state.texenv[8].color;
END
