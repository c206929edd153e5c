// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.2: "genType sqrt (genType x)" (genType is float, vec2, vec3 or vec4)
void main()
{
    gl_Position = vec4(sqrt(4));
}
