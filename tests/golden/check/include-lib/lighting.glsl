// Shared lighting code, found through -I include-lib.
#include "lighting/constants.glsl"
vec3 lambert(vec3 n, vec3 l) { return vec3(max(dot(n, l), 0.0)) * kAmbientScale; }
