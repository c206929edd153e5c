// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.7 "identifier: nondigit / identifier nondigit / identifier digit"
#version 110
void main()
{
    float 2x = 1.0;
    gl_Position = vec4(0.0);
}
