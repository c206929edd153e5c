// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.2 "Initializers for const declarations must be formed from literal values, other const variables (not including function call paramaters), or expressions of these." (a global const, initialized with a comma of constants)
#version 110
const float k = (1.0, 2.0);
void main()
{
    gl_Position = vec4(k);
}
