// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.2: "genType pow (genType x, genType y)" (no vector, float overload)
#version 110
uniform vec3 v;
void main()
{
    gl_Position = vec4(pow(v, 2.0), 1.0);
}
