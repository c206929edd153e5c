!!ARBfp1.0
# SHADOW2D without OPTION ARB_fragment_program_shadow (ARB_fragment_program_shadow)
# FAIL
# EXPECT-ERROR: 5:53 arb-texture-shadow-option
TEX result.color, fragment.texcoord[1], texture[1], SHADOW2D;
END
