// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "If an array is indexed with an expression that is not an integral constant expression or passed as an argument to a function, then its size must be declared before any such use."
// 4.1.9 "Arrays declared as formal parameters in a function declaration must specify a size."
float values[];
float first(float a[2])
{
    return a[0];
}
void main()
{
    values[1] = 1.0;
    gl_FragColor = vec4(first(values));
}
