!!ARBfp1.0
# SHADOWRECT target with TXP and TXB (ARB_fragment_program_shadow)
OPTION ARB_fragment_program_shadow;
TEMP lit, lit2;
TXP lit, fragment.texcoord[1], texture[1], SHADOWRECT;
TXB lit2, fragment.texcoord[1], texture[1], SHADOWRECT;
ADD lit, lit, lit2;
MUL result.color, fragment.color, lit.x;
END
