// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "The sequence ( , ) operator ... returning the type and value of the right-most expression"; 5.8: assignment "will compile only if expression and lvalue have the same type"
uniform float a;
void main()
{
    float y = (2.0 * a, true);
    gl_Position = vec4(y);
}
