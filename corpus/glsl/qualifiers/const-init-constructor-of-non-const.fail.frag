// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.2 "Initializers for const declarations must be formed from literal values, other const variables (not including function call paramaters), or expressions of these."
// 4.3.2 "Constructors may be used in such expressions, but function calls may not."
uniform float u;
void main()
{
    const vec2 v = vec2(u, 1.0);
    gl_FragColor = vec4(v, 0.0, 1.0);
}
