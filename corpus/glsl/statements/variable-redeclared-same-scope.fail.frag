// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 4.2 (scoping of statements): "within one compilation unit, a variable with the same name cannot be re-declared in the same scope."
void main()
{
    float a = 1.0;
    float a = 2.0;
    gl_FragColor = vec4(a);
}
