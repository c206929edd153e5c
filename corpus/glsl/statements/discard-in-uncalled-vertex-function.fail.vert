// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.4: "The discard keyword is only allowed within fragment shaders."
void unused()
{
    discard;
}
void main()
{
    gl_Position = vec4(0.0);
}
