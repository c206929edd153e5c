!!ARBfp1.0
# state.fog.color and state.fog.params: linear fog by hand (ARBfp 3.11.3.2, Table X.2.5)
PARAM fogColor  = state.fog.color;
PARAM fogParams = state.fog.params;      # (density, start, end, 1/(end-start))
TEMP f, base;
SUB f.x, fogParams.z, fragment.fogcoord.x;
MUL_SAT f.x, f.x, fogParams.w;
TEX base, fragment.texcoord[0], texture[0], 2D;
MUL base, base, fragment.color;
LRP result.color.rgb, f.x, base, fogColor;
MOV result.color.a, base.a;
END
