// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3 "Declarations of globals without a qualifier, or with just the const qualifier may include initializers ... Such initializers must have constant type."
// 4.3.1 "For either global or local unqualified variables, the declaration will appear to allocate memory associated with the processor it targets. This variable will provide read/write access to this allocated memory."
#version 110
const float k = 2.0;
float g = 1.0;
vec3 v = vec3(k, 1.0, k * 2.0);
mat2 m = mat2(1.0, 0.0, 0.0, 1.0);
void main()
{
    g = g + 1.0;
    v.x = g;
    gl_Position = vec4(v, m[1][1]);
}
