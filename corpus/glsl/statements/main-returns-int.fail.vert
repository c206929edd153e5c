// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "This function takes no arguments, returns no value, and must be declared as type void"
int main()
{
    gl_Position = vec4(1.0);
    return 0;
}
