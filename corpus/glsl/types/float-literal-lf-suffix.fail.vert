// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.4 floating-constant grammar has no suffix (no f, F, lf)
#version 110
void main()
{
    float x = 1.0lf;
    gl_Position = vec4(x);
}
