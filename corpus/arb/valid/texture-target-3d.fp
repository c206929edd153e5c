!!ARBfp1.0
# TEX with the 3D target: volume noise (ARBfp 3.11.6)
TEMP p, noise;
MUL p, fragment.texcoord[0], program.local[0];
TEX noise, p, texture[0], 3D;
MAD result.color, noise, 0.5, fragment.color;
END
