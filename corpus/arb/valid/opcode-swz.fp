!!ARBfp1.0
# SWZ and SWZ_SAT: extended swizzle with 0, 1 and negation (ARBfp 3.11.5.28)
# Build vectors from components, constants and negated components.
TEMP v0, v1, v2;
SWZ v0, fragment.texcoord[0], x, y, 0, 1;
SWZ v1, fragment.color, -r, g, 1, -0;
SWZ v2, program.local[0], +w, -z, y, x;
SWZ_SAT v2.xy, v0, 1, -x, 0, w;
SWZ v0.zw, v1, a, b, g, r;
ADD v1, v1, v2;
MAD result.color, v0, v1, fragment.color;
END
