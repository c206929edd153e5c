// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "Other binary or unary expressions, non-dereferenced arrays, function names, swizzles with repeated fields, and constants cannot be l-values."
void main()
{
    float a[2];
    float b[2];
    b[0] = 1.0; b[1] = 2.0;
    a = b;
    gl_Position = vec4(a[0]);
}
