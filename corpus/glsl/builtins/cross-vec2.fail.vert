// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.4: "vec3 cross (vec3 x, vec3 y)" (vec3 only)
#version 110
uniform vec2 a;
uniform vec2 b;
void main()
{
    gl_Position = vec4(cross(a, b), 0.0, 1.0);
}
