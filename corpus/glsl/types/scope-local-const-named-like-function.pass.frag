// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.2 "Functions names are always identifiable as function names based on context, and they have their own name space." (a local const named like a user function, the function called in its scope)
#version 110
float halve(float x)
{
    return x * 0.5;
}
void main()
{
    const float halve = 0.5;
    gl_FragColor = vec4(halve(halve));
}
