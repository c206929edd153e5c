!!ARBfp1.0
# Reinhard tone mapping of an HDR rectangle texture at the window position (ARBfp 3.11.6)
PARAM exposure = program.local[0];
TEMP hdr, lum;
TEX hdr, fragment.position, texture[0], RECT;
MUL hdr, hdr, exposure.x;
DP3 lum.x, hdr, { 0.2126, 0.7152, 0.0722, 0 };
ADD lum.y, lum.x, 1.0;
RCP lum.y, lum.y;
MUL result.color.rgb, hdr, lum.y;
MOV result.color.a, 1.0;
END
