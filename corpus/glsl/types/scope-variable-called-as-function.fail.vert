// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.2 "Functions names are always identifiable as function names based on context, and they have their own name space." (a variable is not a function)
#version 110
float scale = 2.0;
void main()
{
    gl_Position = vec4(scale(1.0));
}
