// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "Member declarators do not contain any qualifiers. Nor do they contain any bit fields."
// 4.3 "Function return types and structure fields do not use qualifiers."
struct S {
    uniform float x;
};
void main()
{
    gl_FragColor = vec4(0.0);
}
