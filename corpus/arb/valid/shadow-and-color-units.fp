!!ARBfp1.0
# a shadow unit next to a colour unit, and 2D after SHADOW2D on another unit (ARB_fragment_program_shadow)
OPTION ARB_fragment_program_shadow;
TEMP base, lit;
TEX base, fragment.texcoord[0], texture[0], 2D;
TXP lit, fragment.texcoord[1], texture[1], SHADOW2D;
MAD lit, lit.x, 0.7, 0.3;
MUL result.color, base, lit;
END
