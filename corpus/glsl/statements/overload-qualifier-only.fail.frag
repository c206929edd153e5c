// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "If functions' names and argument types match, then their return type and parameter qualifiers must also match."
void f(in float x) { }
void f(out float x) { x = 1.0; }
void main()
{
    gl_FragColor = vec4(1.0);
}
