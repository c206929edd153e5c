// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.2 "Functions names are always identifiable as function names based on context, and they have their own name space." (a const variable named like a built-in function, the built-in called in its scope)
#version 110
void main()
{
    const float sin = 0.5;
    gl_FragColor = vec4(sin(sin));
}
