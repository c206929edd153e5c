// [config]
// expect_result: fail
// glsl_version: 1.20
// [end config]
// 1.20 4.2: "When a function name is redeclared in a nested scope, it hides all functions declared with that name in the outer scope" (the built-ins are in the scope outside the global one)
#version 120
float exp(float x, float y) { return x + y; }
void main()
{
    gl_Position = vec4(exp(2.0));
}
