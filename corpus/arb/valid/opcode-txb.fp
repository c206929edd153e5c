!!ARBfp1.0
# TXB and TXB_SAT: texture sample with LOD bias from w (ARBfp 3.11.6.3)
# Sharpen distant texels: LOD bias from program.local[0].x.
TEMP tc, base;
MOV tc, fragment.texcoord[0];
MOV tc.w, program.local[0].x;
TXB base, tc, texture[0], 2D;
TXB_SAT base.a, fragment.texcoord[1], texture[1], 2D;
MUL result.color, base, fragment.color;
END
