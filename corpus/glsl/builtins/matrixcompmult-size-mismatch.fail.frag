// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.5: "mat matrixCompMult (mat x, mat y)" ("Similarly for mat": the same matrix type for all arguments and the return)
#version 110
uniform mat2 a;
uniform mat3 b;
void main()
{
    mat3 y = matrixCompMult(a, b);
    gl_FragColor = vec4(y[0], 1.0);
}
