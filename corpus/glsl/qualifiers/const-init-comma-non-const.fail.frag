// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.2 "Initializers for const declarations must be formed from literal values, other const variables (not including function call paramaters), or expressions of these." A uniform is neither, as an operand of a comma.
#version 110
uniform float u;
void main()
{
    const float f = (1.0, u);
    gl_FragColor = vec4(f);
}
