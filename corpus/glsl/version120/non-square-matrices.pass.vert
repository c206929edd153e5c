// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]
// 1.20 4.1.6: "mat2x3 ... mat4x3"; 8.5: transpose and outerProduct
#version 120
uniform mat2x3 m;
attribute vec2 p;
void main()
{
    vec3 v = m * p;
    mat3x2 t = transpose(m);
    mat3 o = outerProduct(v, v);
    gl_Position = vec4(o * v + vec3(t * v, 0.0), 1.0);
}
