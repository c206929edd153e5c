// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "Arrays declared as formal parameters in a function declaration must specify a size."
float first(float a[]);
void main()
{
    gl_FragColor = vec4(0.0);
}
