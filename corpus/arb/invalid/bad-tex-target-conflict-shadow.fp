!!ARBfp1.0
# SHADOW2D and 2D on one unit (ARBfp 3.11.6, ARB_fragment_program_shadow)
# FAIL
# EXPECT-ERROR: 8:44 arb-texture-target-conflict
OPTION ARB_fragment_program_shadow;
TEMP depth, lit;
TEX depth, fragment.texcoord[0], texture[1], 2D;
TEX lit, fragment.texcoord[1], texture[1], SHADOW2D;
MUL result.color, depth, fragment.color;
END
