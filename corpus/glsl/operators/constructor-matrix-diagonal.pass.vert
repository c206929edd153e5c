// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.4.2: "If there is a single scalar parameter to a matrix constructor, it is used to initialize all the components on the matrix's diagonal"; "mat2(vec2, vec2)"; "mat3(float, ... float)"
uniform vec4 v;
void main()
{
    mat4 m = mat4(1.0);
    mat2 a = mat2(v.xy, v.zw);
    mat3 b = mat3(1.0, 0.0, 0.0,
                  0.0, 1.0, 0.0,
                  0.0, 0.0, 1.0);
    mat2 c = mat2(v);
    gl_Position = m * v + vec4(a * v.xy, (b * v.xyz).xy) + vec4(c[0], c[1]);
}
