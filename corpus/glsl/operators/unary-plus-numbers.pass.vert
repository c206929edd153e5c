// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 1.10 5.9: unary '+' on integer and floating-point scalars, vectors and matrices, including
// an element of an array, a structure field and a call's value.
struct S { float x; };
uniform S s;
uniform vec4 a[2];
uniform mat2 m;
float f(float x) { return +x; }
void main()
{
    int i = +1;
    float x = +a[0].x + +s.x + +f(1.0) + float(+i);
    mat2 n = +m;
    gl_Position = vec4(+x, x+ +x, n[0]);
}
