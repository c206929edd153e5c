!!ARBfp1.0
# state.matrix.texture[8]: beyond MAX_TEXTURE_COORDS_ARB (8 on Mesa) (ARBfp 3.11.2 <texCoordNum>)
# FAIL
# EXPECT-ERROR: 5:32 arb-binding-index-range
PARAM r = state.matrix.texture[8].row[0];
MOV result.color, fragment.color;
END
