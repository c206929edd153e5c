// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.7: "the fields of a structure are also selected using the period ( . )" (only declared fields exist)
#version 110
struct S {
    float a;
};
uniform S u;
void main()
{
    gl_Position = vec4(u.b);
}
