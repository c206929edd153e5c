// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1.1: "In a function, writing to an input-only parameter is allowed. Only the function's copy is modified."
#version 110
float f(float x, in vec2 v)
{
    x = x * 2.0;
    v.y = 0.0;
    return x + v.x;
}
void main()
{
    gl_FragColor = vec4(f(1.0, vec2(1.0)));
}
