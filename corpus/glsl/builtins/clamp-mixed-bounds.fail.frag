// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.3: "clamp (genType x, genType minVal, genType maxVal)" and "clamp (genType x, float minVal, float maxVal)" (bounds are both genType or both float)
uniform vec3 v;
void main()
{
    gl_FragColor = vec4(clamp(v, vec3(0.0), 1.0), 1.0);
}
