// [config]
// expect_result: fail
// glsl_version: 1.20
// [end config]
// 1.20 4.6.1: "the invariant qualifier must appear before any use of the variables"... glslang and Mesa: "All uses of invariant must be at global scope"; an invariant declaration inside a function is an error
#version 120
varying vec3 color;
void main()
{
    invariant color;
    color = gl_Color.rgb;
    gl_Position = ftransform();
}
