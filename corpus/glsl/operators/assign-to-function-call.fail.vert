// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "Other binary or unary expressions, non-dereferenced arrays, function names, swizzles with repeated fields, and constants cannot be l-values." (a call result is not an l-value)
float f()
{
    return 1.0;
}
void main()
{
    f() = 2.0;
    gl_Position = vec4(1.0);
}
