// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.1 "In general, the language's use of this character set is case sensitive."
void main()
{
    float value = 1.0;
    gl_Position = vec4(Value);
}
