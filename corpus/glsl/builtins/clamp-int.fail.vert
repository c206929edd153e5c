// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.3: "genType clamp (genType x, genType minVal, genType maxVal)" and "(genType x, float minVal, float maxVal)" (genType is float, vec2, vec3, vec4)
#version 110
uniform int i;
void main()
{
    int c = clamp(i, 0, 3);
    gl_Position = vec4(float(c));
}
