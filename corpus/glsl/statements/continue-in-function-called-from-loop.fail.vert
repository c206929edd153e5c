// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.4: "The continue jump is used only in loops. It skips the remainder of the body of the inner most loop of which it is inside." (a function body is not inside the caller's loop)
void skip()
{
    continue;
}
void main()
{
    for (int i = 0; i < 2; i++)
        skip();
    gl_Position = vec4(0.0);
}
