// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.3: only "If a function returns a value" may a call be used as an expression; 5.9 lists "Function calls that return values."
void nothing()
{
}
void main()
{
    float f = nothing();
    gl_Position = vec4(f);
}
