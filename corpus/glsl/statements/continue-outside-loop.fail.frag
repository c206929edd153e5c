// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.4: "The continue jump is used only in loops."
#version 110
void main()
{
    gl_FragColor = vec4(0.0);
    continue;
}
