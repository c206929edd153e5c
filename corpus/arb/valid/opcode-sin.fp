!!ARBfp1.0
# SIN and SIN_SAT: scalar sine, result replicated (ARBfp 3.11.5.25)
# Wobbly texture coordinates: s += 0.02 * sin(8 t + time).
PARAM time = program.env[0];
TEMP ang, tc;
MAD ang.x, fragment.texcoord[0].y, 8.0, time.x;
SIN ang.y, ang.x;
SIN_SAT ang.z, time.x;
MOV tc, fragment.texcoord[0];
MAD tc.x, ang.y, 0.02, tc.x;
TEX result.color, tc, texture[0], 2D;
END
