// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.8 "Each level of structure has its own namespace for names given in member declarators; such names need only be unique within that namespace."
#version 110
struct Inner {
    float x;
};
struct Outer {
    Inner x;
    float y;
};
float x = 1.0;
void main()
{
    Outer y;
    y.x.x = x;
    y.y = y.x.x;
    gl_Position = vec4(y.y);
}
