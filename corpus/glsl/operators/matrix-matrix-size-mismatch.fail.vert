// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.10: "They require the size of the operands match." (1.10 has square matrices only)
uniform mat2 a;
uniform mat3 b;
void main()
{
    mat3 c = a * b;
    gl_Position = vec4(c[0], 1.0);
}
