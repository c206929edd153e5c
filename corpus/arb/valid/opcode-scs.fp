!!ARBfp1.0
# SCS and SCS_SAT: sine and cosine into x and y only (ARBfp 3.11.5.23)
# Rotate texture coordinates about (0.5, 0.5) by the angle in local 0.
PARAM angle = program.local[0];
TEMP cs, tc, rot;
SCS cs.xy, angle.x;                 # cs = (cos, sin, -, -)
SUB tc, fragment.texcoord[0], { 0.5, 0.5, 0, 0 };
MOV rot, fragment.texcoord[0];
MUL rot.xy, tc.x, cs.xyxy;          # (s cos, s sin)
MAD rot.x, -tc.y, cs.y, rot.x;      # s cos - t sin
MAD rot.y, tc.y, cs.x, rot.y;       # s sin + t cos
ADD rot.xy, rot, 0.5;
SCS_SAT cs.x, angle.y;
TEX result.color, rot, texture[0], 2D;
END
