// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.2 "If it is declared as a parameter in a function definition, it is scoped until the end of that function definition. A function body has a scope nested inside the function's definition."
float f(float x)
{
    return x;
}
void main()
{
    gl_FragColor = vec4(f(1.0) + x);
}
