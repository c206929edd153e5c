!!ARBfp1.0
# texture[4]: beyond the minimum of 2 texture image units (ARBfp 3.11.2 <texImageUnitNum>)
# EXPECT-WARNING: 5:41 arb-limit-portability
TEMP base;
TEX base, fragment.texcoord[0], texture[4], 2D;
MUL result.color, base, fragment.color;
END
