// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 4.1.9 (used by 5.2): "It is illegal to declare an array with a size, and then later (in the same shader) index the same array with an integral constant expression greater than or equal to the declared size."
uniform vec4 w[2];
void main()
{
    gl_Position = w[2];
}
