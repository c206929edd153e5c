!!ARBfp1.0
# per-pixel diffuse + specular bump mapping as in Doom 3-era engines (ARBfp 3.11.5, 3.11.6)
# Normal map on unit 0, diffuse map (gloss in alpha) on unit 1; tangent-space light
# vector in texcoord 1, half vector packed into the secondary colour.
PARAM lightColor = program.env[0];
PARAM specExp = program.env[1];
TEMP N, L, H, diffuse, spec, base;
TEX N, fragment.texcoord[0], texture[0], 2D;
MAD N.xyz, N, 2.0, -1.0;
DP3 L.w, fragment.texcoord[1], fragment.texcoord[1];
RSQ L.w, L.w;
MUL L.xyz, fragment.texcoord[1], L.w;
MAD H, fragment.color.secondary, 2.0, -1.0;
DP3 H.w, H, H;
RSQ H.w, H.w;
MUL H.xyz, H, H.w;
DP3_SAT diffuse.x, N, L;
DP3_SAT spec.x, N, H;
POW spec.x, spec.x, specExp.x;
TEX base, fragment.texcoord[0], texture[1], 2D;
MUL diffuse, base, diffuse.x;
MAD diffuse, spec.x, base.a, diffuse;
MUL result.color.rgb, diffuse, lightColor;
MOV result.color.a, base.a;
END
