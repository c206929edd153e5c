!!ARBfp1.0
# terrain splatting in the style of Unity's compiled shaders, which put their textures on
# image units 8 to 15: units past the eight coordinate sets (ARBfp 3.11.2 <texImageUnitNum>
# is below MAX_TEXTURE_IMAGE_UNITS_ARB, not MAX_TEXTURE_COORDS_ARB)
PARAM c[2] = { program.local[0], { 2, 1, 0.5, 0 } };
TEMP R0, R1, R2, R3;
TEX R0, fragment.texcoord[0], texture[8], 2D;
TEX R1, fragment.texcoord[1], texture[9], 2D;
MUL R1, R1, R0.x;
TEX R2, fragment.texcoord[1], texture[10], 2D;
MAD R1, R2, R0.y, R1;
TEX R2, fragment.texcoord[2], texture[11], 2D;
MAD R1, R2, R0.z, R1;
TEX R2, fragment.texcoord[2], texture[12], 3D;
MAD R1, R2, R0.w, R1;
TEX R3, fragment.texcoord[3], texture[13], 2D;
MAD R3.xyz, R3, c[1].x, -c[1].y;
DP3_SAT R3.w, R3, c[0];
TEX R2, fragment.texcoord[4], texture[14], CUBE;
MUL R2, R2, R3.w;
TEX R3, fragment.texcoord[5], texture[15], 2D;
MAD R2, R3, c[1].z, R2;
MUL result.color, R1, R2;
END
