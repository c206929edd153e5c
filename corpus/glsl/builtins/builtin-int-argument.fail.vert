// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8: "genType is used as the argument" (float, vec2, vec3, vec4); 6.1: "No promotion or demotion of the return type or input argument types is done."
#version 110
void main()
{
    gl_Position = vec4(sin(1));
}
