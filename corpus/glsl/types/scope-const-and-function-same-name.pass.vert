// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.2 "All variables in the same scope share the same name space. Functions names are always identifiable as function names based on context, and they have their own name space." (a const variable named like a function declared before it, both used)
#version 110
float scale(float x)
{
    return x * 2.0;
}
const float scale = 2.0;
void main()
{
    const float offset = 1.0;
    gl_Position = vec4(scale(scale) + offset);
}
