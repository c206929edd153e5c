// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.2: "Any expression whose type evaluates to a Boolean can be used as the conditional expression"
uniform int k;
void main()
{
    gl_Position = vec4(0.0);
    if (k)
        gl_Position = vec4(1.0);
}
