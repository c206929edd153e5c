// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.6 "The following are the keywords in the language, and cannot be used for any other purpose than that defined by this document"
void main()
{
    float bool = 1.0;
    gl_Position = vec4(0.0);
}
