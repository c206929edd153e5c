// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "All functions must be either declared with a prototype or defined with a body before they are called."
void main()
{
    gl_Position = vec4(later(1.0));
}
float later(float x)
{
    return x;
}
