!!ARBfp1.0
# EX2 and EX2_SAT: scalar base-2 exponential (ARBfp 3.11.5.9)
# Exponential fog evaluated by hand: f = 2^(-density * log2(e) * z).
PARAM fogParams = state.fog.params;
PARAM fogColor = state.fog.color;
TEMP f, base;
MUL f.x, fogParams.x, fragment.fogcoord.x;
MUL f.x, f.x, 1.442695;
EX2_SAT f.x, -f.x;
EX2 f.y, fogParams.w;
TEX base, fragment.texcoord[0], texture[0], 2D;
LRP result.color.rgb, f.x, base, fogColor;
MOV result.color.a, base.a;
END
