!!ARBfp1.0
# night vision: luminance, animated 3D noise, green tint (ARBfp 3.11.6)
PARAM time = program.env[0];
PARAM green = { 0.1, 0.95, 0.2, 1 };
TEMP c, n, tc;
TEX c, fragment.texcoord[0], texture[0], 2D;
DP3 c, c, { 0.3, 0.59, 0.11, 0 };
MOV tc, fragment.texcoord[1];
MOV tc.z, time.x;
TEX n, tc, texture[1], 3D;
MAD c, n, 0.2, c;
MUL result.color, c, green;
END
