// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "The logical binary operators and (&&), or ( | | ), and exclusive or (^^). They operate only on two Boolean expressions"
uniform int a;
uniform int b;
void main()
{
    bool c = a && b;
    gl_FragColor = vec4(float(c));
}
