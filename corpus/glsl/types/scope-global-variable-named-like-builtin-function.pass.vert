// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.2 "Functions names are always identifiable as function names based on context, and they have their own name space."
#version 110
float sin = 0.5;
void main()
{
    gl_Position = vec4(sin(sin));
}
