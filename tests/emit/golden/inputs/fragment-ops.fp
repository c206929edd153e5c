!!ARBfp1.0
# CMP, LRP, KIL, SCS, SGE/SLT, POW, FRC, TXB, TXP on CUBE and RECT, env/local parameters.
PARAM e = program.env[2];
PARAM l = program.local[0];
TEMP a, b, c;
KIL fragment.texcoord[0];
KIL -a.xyzx;
TXB a, fragment.texcoord[0], texture[0], 2D;
TXP b, fragment.texcoord[1], texture[1], CUBE;
TEX c, fragment.texcoord[2], texture[2], RECT;
CMP a.xyw, -a, b, c;
LRP_SAT b, e.x, a, c;
SCS c.xy, a.w;
SGE a.x, b, c;
SLT a.yz, b, c.x;
POW b.w, l.x, e.y;
FRC c.zw, b;
ADD result.color, a, b;
END
