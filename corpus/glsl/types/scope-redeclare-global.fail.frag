// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.2 "Otherwise, within one compilation unit, a variable with the same name cannot be re-declared in the same scope. However, a nested scope can override an outer scope's declaration of a particular variable name."
float x;
vec2 x;
void main()
{
    gl_FragColor = vec4(0.0);
}
