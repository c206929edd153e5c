// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.3: "If a function returns a value, then a call to that function may be used as an expression, whose type will be the type that was used to declare or define the function."
#version 110
vec2 half2(vec2 v)
{
    return v * 0.5;
}
void main()
{
    gl_Position = vec4(half2(vec2(1.0, 2.0)), half2(vec2(3.0)).x, 1.0);
}
