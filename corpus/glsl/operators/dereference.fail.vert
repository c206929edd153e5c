// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.1: "There is no address-of operator nor a dereference operator."; grammar note "No '*' or '&' unary ops. Pointers are not supported."
uniform float f;
void main()
{
    float g = *f;
    gl_Position = vec4(g);
}
