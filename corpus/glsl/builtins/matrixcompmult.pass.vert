// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8.5: "mat matrixCompMult (mat x, mat y) Multiply matrix x by matrix y component-wise"
uniform mat2 a;
uniform mat3 b;
uniform mat4 c;
void main()
{
    mat2 x = matrixCompMult(a, a);
    mat3 y = matrixCompMult(b, b);
    mat4 z = matrixCompMult(c, c);
    gl_Position = z[0] + vec4(y[1], x[0][1]);
}
