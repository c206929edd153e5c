// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 2.1: "a shader ... is a set of strings ... compiled ... into a shader object"; 6.1: a program needs main() "in one of the shaders": a shader object without main() compiles (glCompileShader)
#version 110
// A function library: linked with the shaders that call it.
vec3 blinn(vec3 n, vec3 l, vec3 v, float shininess)
{
    vec3 h = normalize(l + v);
    return vec3(max(dot(n, l), 0.0), pow(max(dot(n, h), 0.0), shininess), 0.0);
}
