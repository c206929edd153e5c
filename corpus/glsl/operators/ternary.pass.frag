// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.9: "The ternary selection operator (?:) ... The second and third expressions must be the same type, but can be of any type other than an array."
#version 110
struct S {
    float x;
};
uniform bool p;
uniform vec4 a;
uniform vec4 b;
void main()
{
    vec4 c = p ? a : b;
    S s = p ? S(1.0) : S(2.0);
    mat2 m = !p ? mat2(1.0) : mat2(2.0);
    gl_FragColor = c + vec4(s.x, m[0][0], 0.0, 0.0);
}
