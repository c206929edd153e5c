!!ARBfp1.0
# COS and COS_SAT: scalar cosine, result replicated (ARBfp 3.11.5.4)
# Animated stripes: 0.5 + 0.5 * cos(2 pi s + time).
PARAM time = program.env[0];
TEMP ang, wave;
MUL ang.x, fragment.texcoord[0].x, 6.2831853;
ADD ang.x, ang.x, time.x;
COS wave, ang.x;
COS_SAT wave.w, time.y;
MAD_SAT result.color, wave, 0.5, 0.5;
END
