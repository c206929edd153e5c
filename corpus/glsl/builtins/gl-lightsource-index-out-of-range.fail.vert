// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.5: "uniform gl_LightSourceParameters gl_LightSource[gl_MaxLights];"; 4.1.9: indexing "with an integral constant expression greater than or equal to the declared size" is illegal
void main()
{
    gl_Position = ftransform() + gl_LightSource[gl_MaxLights].position;
}
