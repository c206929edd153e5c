// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.2 "Initializers for const declarations must be formed from literal values, other const variables (not including function call paramaters), or expressions of these." A comma of constants indexes a const matrix, and a const so initialized initializes another.
#version 110
void main()
{
    const mat2 m = mat2(1.0, 2.0, 3.0, 4.0);
    const vec2 c = m[0, 1];
    const float x = c[int(c.y) - 3, 0];
    gl_FragColor = vec4(c, x, 1.0);
}
