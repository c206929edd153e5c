// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "Macro expansion is not done on lines containing #extension and #version directives."
// 3.3 "#version number where number must be 110 ... in which case the directive will be accepted with no errors or warnings."
#version __VERSION__
void main()
{
    gl_Position = vec4(0.0);
}
