// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.4.1/5.4.2: scalar, vector and matrix constructors take scalars, vectors or matrices; 5.4: parameters "must be of sufficient size and correct type"
#version 110
struct S {
    float a;
};
uniform S s;
void main()
{
    float f = float(s);
    gl_FragColor = vec4(f);
}
