// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "Any directive not listed above will cause a diagnostic message and make the implementation treat the shader as ill-formed."
#warning this is not a GLSL directive
void main()
{
    gl_FragColor = vec4(0.0);
}
