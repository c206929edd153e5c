// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.5: "The component selection syntax allows multiple components to be selected by appending their names"; the result is a "scalar or vector type", and there is no vector larger than vec4
#version 110
uniform vec4 v;
void main()
{
    gl_FragColor = v.xyzwx.xyzw;
}
