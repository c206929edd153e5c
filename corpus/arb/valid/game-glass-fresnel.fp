!!ARBfp1.0
# glass: cube-map reflection blended by a Fresnel power term (ARBfp 3.11.5.20, 3.11.6)
PARAM fresnel = program.local[0];       # (bias, scale, power, 0)
TEMP N, V, R, env, f;
DP3 N.w, fragment.texcoord[0], fragment.texcoord[0];
RSQ N.w, N.w;
MUL N.xyz, fragment.texcoord[0], N.w;
DP3 V.w, fragment.texcoord[1], fragment.texcoord[1];
RSQ V.w, V.w;
MUL V.xyz, fragment.texcoord[1], V.w;
DP3 R.w, N, V;
MUL R.xyz, N, R.w;
MAD R.xyz, R, 2.0, -V;                  # R = 2 (N.V) N - V
TEX env, R, texture[0], CUBE;
ABS f.x, R.w;
SUB f.x, 1.0, f.x;
POW f.x, f.x, fresnel.z;
MAD_SAT f.x, f.x, fresnel.y, fresnel.x;
LRP result.color, f.x, env, fragment.color;
END
