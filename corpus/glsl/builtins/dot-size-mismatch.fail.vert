// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.4: "float dot (genType x, genType y)" (same genType)
#version 110
uniform vec3 a;
uniform vec4 b;
void main()
{
    gl_Position = vec4(dot(a, b));
}
