// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.9: "The logical binary operators and (&&), or ( | | ), and exclusive or (^^). They operate only on two Boolean expressions" and "The logical unary operator not (!)"
#version 110
uniform bool a;
uniform bool b;
void main()
{
    bool c = (a && b) || (a ^^ b) || !a;
    gl_FragColor = vec4(float(c));
}
