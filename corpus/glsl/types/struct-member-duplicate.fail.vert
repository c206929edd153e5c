// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "Each level of structure has its own namespace for names given in member declarators; such names need only be unique within that namespace."
#version 110
struct S {
    float x;
    vec2 x;
};
void main()
{
    gl_Position = vec4(0.0);
}
