// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.1 "Functions that do not return a value must be declared as void. There is no default function return type."
#version 110
vec4 result;
void store(vec4 v)
{
    result = v;
}
float one(void)
{
    return 1.0;
}
void main()
{
    store(vec4(one()));
    gl_Position = result;
}
