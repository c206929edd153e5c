// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.4.2: "If more components are provided in the last used argument to a constructor than are needed to initialize the constructed value, the left most components of that argument are used, and the remaining ones are ignored."
#version 110
uniform mat3 m;
uniform vec3 v;
void main()
{
    vec4 a = vec4(m);
    mat2 b = mat2(v, v);
    mat3 c = mat3(vec4(1.0), vec4(2.0), vec4(3.0));
    gl_Position = a + vec4(b[1], c[2].xy);
}
