// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.8: "genType dFdy (genType p)" (genType is a float type)
#version 110
uniform int i;
void main()
{
    gl_FragColor = vec4(dFdy(i));
}
