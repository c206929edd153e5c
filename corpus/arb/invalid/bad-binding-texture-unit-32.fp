!!ARBfp1.0
# texture[32]: beyond MAX_TEXTURE_IMAGE_UNITS_ARB (32 on Mesa 22.3) (ARBfp 3.11.2 <texImageUnitNum>)
# FAIL
# EXPECT-ERROR: 5:49 arb-binding-index-range
TEX result.color, fragment.texcoord[0], texture[32], 2D;
END
