// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.1: "unary (tilde is reserved) + - ~ !" and "Those marked reserved are illegal."
uniform int a;
void main()
{
    int c = ~a;
    gl_FragColor = vec4(float(c));
}
