// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8.3: abs, sign, floor, ceil, fract, "mod (genType x, float y)", "mod (genType x, genType y)", min/max "(genType x, float y)", "clamp (genType x, float minVal, float maxVal)", "mix (genType x, genType y, float a)", "step (float edge, genType x)", "smoothstep (float edge0, float edge1, genType x)"
#version 110
uniform vec3 v;
uniform vec3 w;
uniform float f;
void main()
{
    vec3 a = abs(v) + sign(v) + floor(v) + ceil(v) + fract(v);
    vec3 b = mod(v, f) + mod(v, w) + min(v, w) + min(v, f) + max(v, w) + max(v, f);
    vec3 c = clamp(v, w, w) + clamp(v, 0.0, 1.0) + mix(v, w, w) + mix(v, w, 0.5);
    vec3 d = step(w, v) + step(0.5, v) + smoothstep(v, w, v) + smoothstep(0.0, 1.0, v);
    float e = abs(f) + mod(f, 2.0) + clamp(f, 0.0, 1.0) + mix(f, 1.0, f) + step(f, 0.5);
    gl_Position = vec4(a + b + c + d, e);
}
