// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "The name shares the same name space as other variables and types, with the same scoping rules." (once hidden by a variable, the name is not a type in that scope)
struct S {
    float x;
};
void main()
{
    float S = 1.0;
    S s;
    gl_FragColor = vec4(S);
}
