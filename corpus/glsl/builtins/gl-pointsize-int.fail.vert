// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.1: "float gl_PointSize;"; 5.8: assignment "will compile only if expression and lvalue have the same type."
void main()
{
    gl_Position = vec4(0.0);
    gl_PointSize = 1;
}
