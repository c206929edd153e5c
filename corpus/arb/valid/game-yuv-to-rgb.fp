!!ARBfp1.0
# video playback: planar Y and UV textures converted to RGB (ARBfp 3.11.5.5)
PARAM yuv2r = { 1.164, 0.0, 1.596, 0 };
PARAM yuv2g = { 1.164, -0.391, -0.813, 0 };
PARAM yuv2b = { 1.164, 2.018, 0.0, 0 };
PARAM offs  = { -0.0625, -0.5, -0.5, 0 };
TEMP yuv, uv;
TEX yuv.x, fragment.texcoord[0], texture[0], 2D;
TEX uv, fragment.texcoord[1], texture[1], 2D;
MOV yuv.yz, uv.xxyw;
MOV yuv.w, 0.0;
ADD yuv, yuv, offs;
DP3_SAT result.color.r, yuv, yuv2r;
DP3_SAT result.color.g, yuv, yuv2g;
DP3_SAT result.color.b, yuv, yuv2b;
MOV result.color.a, 1.0;
END
