// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.5 lists only matrixCompMult; outerProduct (GLSL 1.20) is not a 1.10 built-in
uniform vec2 a;
void main()
{
    mat2 m = outerProduct(a, a);
    gl_FragColor = vec4(m[0], m[1]);
}
