!!ARBfp1.0
# NV_fragment_program: precision, SHORT storage, derivatives, RFL, X2D, TXD, condition codes.
OPTION NV_fragment_program;
SHORT TEMP h;
TEMP t, r;
MULH h, fragment.color, fragment.texcoord[0];
ADDX r, h, -|fragment.texcoord[1]|;
DDX t.xy, fragment.texcoord[0];
DDYC t.zw, fragment.texcoord[0].xyxy;
RFL r.xyz, fragment.texcoord[1], r;
X2D r.zw, fragment.texcoord[0], t, fragment.color;
TXD t, fragment.texcoord[0], t.xyxy, t.zwzw, texture[0], 2D;
KIL LT.zwzw;
SNE_SAT r.x (GE.z), r, h;
MOVR result.color, r;
END
