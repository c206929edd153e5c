!!ARBfp1.0
# DST and DST_SAT: distance vector (1, d, d*d, 1/d) (ARBfp 3.11.5.8)
# Per-pixel light attenuation from the light vector interpolated in texcoord 1.
PARAM atten = state.light[0].attenuation;
TEMP d2, dinv, att;
DP3 d2, fragment.texcoord[1], fragment.texcoord[1];
RSQ dinv, d2.x;
DST att, d2, dinv;
DP3 att.x, att, atten;           # kc + kl*d + kq*d*d
RCP att.x, att.x;
DST_SAT att.yzw, d2, dinv;
MUL result.color, fragment.color, att.x;
END
