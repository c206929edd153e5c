!!ARBfp1.0
# TEX with the 1D target: toon ramp lookup (ARBfp 3.11.2 <texTarget>, 3.11.6)
TEMP ndl, ramp;
DP3_SAT ndl, fragment.texcoord[0], fragment.texcoord[1];
TEX ramp, ndl, texture[1], 1D;
MUL result.color, ramp, fragment.color;
END
