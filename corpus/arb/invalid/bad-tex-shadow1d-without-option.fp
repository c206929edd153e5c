!!ARBfp1.0
# SHADOW1D without OPTION ARB_fragment_program_shadow (ARB_fragment_program_shadow)
# FAIL
# EXPECT-ERROR: 6:53 arb-texture-shadow-option
OPTION ARB_precision_hint_fastest;
TXP result.color, fragment.texcoord[0], texture[0], SHADOW1D;
END
