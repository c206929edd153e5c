// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.7 "identifier: nondigit / identifier nondigit / identifier digit"
#version 110
void main()
{
    float x1 = 1.0;
    float a2b3 = 2.0;
    float ABCxyz0123456789 = 3.0;
    gl_Position = vec4(x1, a2b3, ABCxyz0123456789, 1.0);
}
