// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.2 "It is an error to write to a const variable outside of its declaration, so they must be initialized when declared."
// 4.3.2 "The const qualifier can be used with any of the basic data types."
// 4.3.2 "Initializers for const declarations must be formed from literal values, other const variables (not including function call paramaters), or expressions of these."
// 4.3.2 "Constructors may be used in such expressions, but function calls may not." (constructors allowed)
// 4.3.2 "const vec3 zAxis = vec3 (0.0, 0.0, 1.0);"
#version 110
const vec3 zAxis = vec3 (0.0, 0.0, 1.0);
const float pi = 3.14159;
const float twoPi = 2.0 * pi;
const int n = 4;
const int m = n * 2 - 1;
const bool yes = true;
const bool no = !yes;
const ivec2 iv = ivec2(n, m);
const bvec3 bv = bvec3(yes, no, yes);
const mat2 rot = mat2(0.0, 1.0, -1.0, 0.0);
const vec4 combined = vec4(zAxis * twoPi, float(m));
void main()
{
    gl_Position = combined + vec4(rot[0], float(iv.y), bv.x ? 1.0 : 0.0);
}
