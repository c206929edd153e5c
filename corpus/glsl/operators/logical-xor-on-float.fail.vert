// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "The logical binary operators and (&&), or ( | | ), and exclusive or (^^). They operate only on two Boolean expressions"
#version 110
uniform float a;
void main()
{
    bool c = a ^^ 1.0;
    gl_Position = vec4(float(c));
}
