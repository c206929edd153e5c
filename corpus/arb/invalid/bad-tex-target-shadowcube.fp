!!ARBfp1.0
# SHADOWCUBE is not among the shadow targets even with the option (ARB_fragment_program_shadow <shadowTarget>)
# FAIL
# EXPECT-ERROR: 6:53 arb-texture-target
OPTION ARB_fragment_program_shadow;
TEX result.color, fragment.texcoord[0], texture[0], SHADOWCUBE;
END
