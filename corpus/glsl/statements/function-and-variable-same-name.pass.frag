// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 4.2 (used by 6.1): "All variables in the same scope share the same name space. Functions names are always identifiable as function names based on context, and they have their own name space."
#version 110
float scale = 2.0;
float scale(float x)
{
    return x * 0.5;
}
void main()
{
    gl_FragColor = vec4(scale(scale));
}
