!!ARBfp1.0
# cel shading: N.L through a 1D ramp texture (ARBfp 3.11.6)
PARAM lightDir = program.local[0];
TEMP n, ndl, shade, base;
DP3 n.w, fragment.texcoord[1], fragment.texcoord[1];
RSQ n.w, n.w;
MUL n.xyz, fragment.texcoord[1], n.w;
DP3_SAT ndl.x, n, lightDir;
MOV ndl.yzw, 0.5;
TEX shade, ndl, texture[1], 1D;
TEX base, fragment.texcoord[0], texture[0], 2D;
MUL result.color, base, shade;
END
