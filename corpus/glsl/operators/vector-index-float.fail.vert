// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.5: "Any integer expression can be used as the subscript."
#version 110
void main()
{
    vec4 pos = vec4(1.0, 2.0, 3.0, 4.0);
    float z = pos[2.0];
    gl_Position = vec4(z);
}
