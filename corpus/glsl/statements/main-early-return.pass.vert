// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.4: "The function main can use return. This simply causes main to exit in the same way as when the end of the function had been reached."
uniform bool early;
void main()
{
    gl_Position = vec4(0.0);
    if (early)
        return;
    gl_Position = vec4(1.0);
}
