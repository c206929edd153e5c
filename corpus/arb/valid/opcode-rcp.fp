!!ARBfp1.0
# RCP and RCP_SAT: scalar reciprocal (ARBfp 3.11.5.21)
# Manual perspective divide before a plain TEX.
TEMP tc, invq;
RCP invq.x, fragment.texcoord[0].w;
RCP_SAT invq.y, program.local[3].z;
MUL tc, fragment.texcoord[0], invq.x;
TEX result.color, tc, texture[0], 2D;
END
