!!ARBfp1.0
# POW and POW_SAT: scalar power (ARBfp 3.11.5.20)
# Specular highlight: (N.H)^exponent with the half vector in texcoord 1.
PARAM specExp = program.local[0];
TEMP h, nh, spec;
DP3 h.w, fragment.texcoord[1], fragment.texcoord[1];
RSQ h.w, h.w;
MUL h.xyz, fragment.texcoord[1], h.w;
DP3_SAT nh.x, h, { 0, 0, 1 };
POW spec.x, nh.x, specExp.x;
POW_SAT spec.y, nh.x, specExp.y;
MAD result.color, spec.x, state.lightprod[0].specular, fragment.color;
END
