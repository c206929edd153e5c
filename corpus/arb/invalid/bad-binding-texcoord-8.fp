!!ARBfp1.0
# fragment.texcoord[8]: beyond MAX_TEXTURE_COORDS_ARB (8 on Mesa) (ARBfp 3.11.2 <texCoordNum>)
# FAIL
# EXPECT-ERROR: 5:37 arb-binding-index-range
MOV result.color, fragment.texcoord[8];
END
