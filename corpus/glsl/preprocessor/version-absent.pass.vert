// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "shaders that do not include a #version directive will be treated as targeting version 110."
void main()
{
    gl_Position = vec4(0.0);
}
