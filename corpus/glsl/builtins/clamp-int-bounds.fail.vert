// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.3: "genType clamp (genType x, float minVal, float maxVal)"; 6.1: "No promotion or demotion of the return type or input argument types is done."
#version 110
uniform vec3 v;
void main()
{
    gl_Position = vec4(clamp(v, 0, 1), 1.0);
}
