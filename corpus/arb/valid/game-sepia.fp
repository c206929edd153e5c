!!ARBfp1.0
# sepia post-process: luminance, tone, blend by amount (ARBfp 3.11.5.5, 3.11.5.14)
PARAM lumWeights = { 0.299, 0.587, 0.114, 0 };
PARAM sepiaTone = { 1.2, 1.0, 0.8, 1.0 };
PARAM amount = program.local[0];
TEMP c, gray;
TEX c, fragment.texcoord[0], texture[0], 2D;
DP3 gray, c, lumWeights;
MUL gray, gray, sepiaTone;
LRP result.color.rgb, amount.x, gray, c;
MOV result.color.a, c.a;
END
