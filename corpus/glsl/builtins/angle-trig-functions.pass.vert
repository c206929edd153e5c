// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8.1: "genType radians (genType degrees)", "degrees", "sin", "cos", "tan", "asin", "acos", "atan (genType y, genType x)", "atan (genType y_over_x)"
uniform vec4 v;
uniform float f;
void main()
{
    vec4 a = radians(v) + degrees(v) + sin(v) + cos(v) + tan(v);
    vec3 b = asin(v.xyz) + acos(v.xyz);
    vec2 c = atan(v.xy, v.zw) + atan(v.xy);
    float d = atan(f) + sin(f) + radians(f);
    gl_Position = a + vec4(b, d) + vec4(c, c);
}
