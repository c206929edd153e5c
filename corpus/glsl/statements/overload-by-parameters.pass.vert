// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1: "Function names can be overloaded. This allows the same function name to be used for multiple functions, as long as the argument list types differ."
float f(float x) { return x; }
float f(vec2 x) { return x.y; }
float f(float x, float y) { return x + y; }
float f(int x) { return float(x); }
void main()
{
    gl_Position = vec4(f(1.0), f(vec2(2.0)), f(1.0, 2.0), f(3));
}
