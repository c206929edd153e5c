// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.5: "mat matrixCompMult (mat x, mat y)" (matrices only)
uniform vec4 a;
void main()
{
    gl_Position = matrixCompMult(a, a);
}
