// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.4: "const int gl_MaxLights = 8;"; 4.3.2: "It is an error to write to a const variable outside of its declaration"
#version 110
void main()
{
    gl_MaxLights = 4;
    gl_Position = vec4(0.0);
}
