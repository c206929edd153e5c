// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.6 "The following are the keywords reserved for future use. Using them will result in an error"
void main()
{
    float sampler2DRect = 1.0;
    gl_Position = vec4(0.0);
}
