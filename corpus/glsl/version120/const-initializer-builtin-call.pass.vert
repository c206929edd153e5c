// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]
// 1.20 4.3.3: a constant expression is "a built-in function call whose arguments are all constant expressions, with the exception of the texture lookup functions"
#version 120
const float half_sqrt2 = sqrt(2.0) * 0.5;
const vec3 axis = normalize(vec3(1.0, 1.0, 0.0));
void main()
{
    gl_Position = vec4(axis * half_sqrt2, 1.0);
}
