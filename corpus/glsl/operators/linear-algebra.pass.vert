// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.10: "The exceptions are matrix multiplied by vector, vector multiplied by matrix, and matrix multiplied by matrix. These do not operate component-wise, but rather perform the correct linear algebraic multiply."
#version 110
uniform mat3 m;
uniform mat3 n;
uniform vec3 v;
uniform mat2 m2;
uniform vec2 v2;
void main()
{
    vec3 a = v * m;
    vec3 b = m * v;
    mat3 r = m * n;
    vec3 c = v * v;
    vec2 d = m2 * v2 + v2 * m2;
    gl_Position = vec4(a + b + r[0] + c, d.x);
}
