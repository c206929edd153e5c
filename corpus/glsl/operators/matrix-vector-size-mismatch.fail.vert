// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.10: matrix/vector multiplications "require the size of the operands match."; 5.9: "one can be a vector and the other a matrix with the same dimensional size of the vector"
uniform mat3 m;
uniform vec4 v;
void main()
{
    gl_Position = m * v;
}
