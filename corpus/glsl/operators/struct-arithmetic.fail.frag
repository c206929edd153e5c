// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.7: "In total, the following operators are allowed to operate on a structure: structure field selector . equality == != assignment ="
#version 110
struct S {
    float a;
};
uniform S u;
uniform S v;
void main()
{
    S s = u + v;
    gl_FragColor = vec4(s.a);
}
