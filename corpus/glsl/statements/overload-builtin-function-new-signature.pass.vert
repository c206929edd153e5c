// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1: "Function names can be overloaded ... as long as the argument list types differ."
float dot(float a, float b, float c)
{
    return a * b * c;
}
void main()
{
    gl_Position = vec4(dot(1.0, 2.0, 3.0) + dot(vec2(1.0), vec2(2.0)));
}
