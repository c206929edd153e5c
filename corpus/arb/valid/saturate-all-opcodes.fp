!!ARBfp1.0
# every _SAT opcode form of ARBfp 3.11.2 <VECTORop> .. <SAMPLEop> (ARBfp 3.11.4.3)
TEMP t0, t1, t2, acc;
TEX_SAT t0, fragment.texcoord[0], texture[0], 2D;
TXP_SAT t1, fragment.texcoord[1], texture[1], 2D;
TXB_SAT t2, fragment.texcoord[0], texture[0], 2D;
ABS_SAT acc, t0;
ADD_SAT acc, acc, t1;
CMP_SAT acc, t2, acc, t1;
COS_SAT acc.x, t0.x;
DP3_SAT acc.y, t0, t1;
DP4_SAT acc.z, t0, t1;
DPH_SAT acc.w, t0, t1;
DST_SAT t1, t0, t2;
EX2_SAT t2.x, acc.x;
FLR_SAT t2.y, acc;
FRC_SAT t2.z, acc;
LG2_SAT t2.w, acc.y;
LIT_SAT t0, acc;
LRP_SAT acc, t0, t1, t2;
MAD_SAT acc, acc, t0, t1;
MAX_SAT acc, acc, t2;
MIN_SAT acc, acc, t1;
MOV_SAT t0, acc;
MUL_SAT t0, t0, acc;
POW_SAT t1.x, t0.x, acc.y;
RCP_SAT t1.y, t0.z;
RSQ_SAT t1.z, t0.w;
SCS_SAT t2.xy, t0.x;
SGE_SAT t1.w, t0, acc;
SIN_SAT t2.z, acc.z;
SLT_SAT t2.w, acc, t0;
SUB_SAT acc, t1, t2;
SWZ_SAT t0, acc, z, y, x, 1;
XPD_SAT t1.xyz, t0, acc;
MUL result.color, t1, t2;
END
