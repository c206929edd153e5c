!!ARBfp1.0
# DPH and DPH_SAT: homogeneous dot product xyz.xyz + w (ARBfp 3.11.5.7)
# User clip plane evaluated per fragment: kill what lies behind the plane.
PARAM plane = program.env[1];
TEMP dist;
DPH dist, fragment.texcoord[1], plane;
KIL dist;
DPH_SAT dist, fragment.texcoord[1], plane;
MUL result.color, fragment.color, dist;
END
