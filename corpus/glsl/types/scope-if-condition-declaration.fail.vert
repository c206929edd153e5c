// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.2 "The if statement's expression does not allow new variables to be declared, hence does not form a new scope."
#version 110
uniform float a;
void main()
{
    float x = 0.0;
    if (bool b = a > 0.0)
        x = 1.0;
    gl_Position = vec4(x);
}
