// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "#version number where number must be 110 ... in which case the directive will be accepted with no errors or warnings."
#version
void main()
{
    gl_FragColor = vec4(0.0);
}
