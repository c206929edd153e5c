// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.8 "The name shares the same name space as other variables and types, with the same scoping rules." (a nested scope can hide the type name)
struct S {
    float x;
};
void main()
{
    S s = S(1.0);
    {
        float S = s.x;
        gl_FragColor = vec4(S);
    }
}
