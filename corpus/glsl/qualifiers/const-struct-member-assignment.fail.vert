// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.2 "It is an error to write to a const variable outside of its declaration, so they must be initialized when declared."
// 4.3.2 "Structure variables can be declared as const, and initialized with a structure constructor."
#version 110
struct S {
    float x;
};
const S s = S(1.0);
void main()
{
    s.x = 2.0;
    gl_Position = vec4(s.x);
}
