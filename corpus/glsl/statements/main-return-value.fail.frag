// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: main "returns no value"; 6.4: "The function main can use return. This simply causes main to exit"
#version 110
void main()
{
    gl_FragColor = vec4(1.0);
    return 1.0;
}
