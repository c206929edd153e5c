// [config]
// expect_result: fail
// glsl_version: 1.20
// [end config]
// 1.20 4.3.3: a constant expression is "a built-in function call whose arguments are all constant expressions, with the exception of the texture lookup functions, the noise functions, and ftransform."
#version 120
void main()
{
    const vec2 n = (vec2(0.0), noise2(0.5));
    gl_FragColor = vec4(n, 0.0, 1.0);
}
