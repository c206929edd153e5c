!!ARBfp1.0
# SHADOW1D target with OPTION ARB_fragment_program_shadow (ARB_fragment_program_shadow)
OPTION ARB_fragment_program_shadow;
TEMP lit;
TEX lit, fragment.texcoord[0], texture[0], SHADOW1D;
MUL result.color, fragment.color, lit.x;
END
