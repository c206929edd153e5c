// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: arithmetic binary operators "operate on integer and floating-point typed expressions (including vectors and matrices)."
#version 110
uniform bvec2 a;
void main()
{
    bvec2 c = a * a;
    gl_Position = vec4(float(c.x));
}
