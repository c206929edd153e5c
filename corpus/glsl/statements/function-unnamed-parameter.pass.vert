// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1: "name : empty | identifier" ... "Hence, function definitions can have unnamed arguments."
float second(float, float y)
{
    return y;
}
void main()
{
    gl_Position = vec4(second(1.0, 2.0));
}
