// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4 "All variables and functions must be declared before being used."
void main()
{
    gl_FragColor = vec4(x);
    float x = 1.0;
}
