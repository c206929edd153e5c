// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.6 "the OpenGL Shading Language defines support for 2x2, 3x3, and 4x4 matrices of floating point numbers."
void main()
{
    mat5 m;
    gl_FragColor = vec4(0.0);
}
