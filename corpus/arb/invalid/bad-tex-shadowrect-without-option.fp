!!ARBfp1.0
# SHADOWRECT without OPTION ARB_fragment_program_shadow (ARB_fragment_program_shadow)
# FAIL
# EXPECT-ERROR: 5:53 arb-texture-shadow-option
TXB result.color, fragment.texcoord[0], texture[0], SHADOWRECT;
END
