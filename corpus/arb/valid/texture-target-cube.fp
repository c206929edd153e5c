!!ARBfp1.0
# TEX with the CUBE target: reflection vector into an environment map (ARBfp 3.11.6)
# texcoord 0 = normal, texcoord 1 = eye vector, both in world space.
TEMP n, r, env;
DP3 n.w, fragment.texcoord[0], fragment.texcoord[0];
RSQ n.w, n.w;
MUL n.xyz, fragment.texcoord[0], n.w;
DP3 r.w, n, fragment.texcoord[1];
MUL r.xyz, n, r.w;
MAD r, r, -2.0, fragment.texcoord[1];        # R = I - 2 (N.I) N
TEX env, r, texture[0], CUBE;
MUL result.color, env, fragment.color;
END
