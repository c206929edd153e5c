// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.4 floating-constant grammar has no suffix (no f, F, lf)
void main()
{
    float x = 1e3f;
    gl_Position = vec4(x);
}
