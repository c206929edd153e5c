// [config]
// expect_result: fail
// glsl_version: 1.20
// [end config]
// 1.20 6.1: "Function declarations (prototypes) cannot occur inside of functions; they must be at global scope"
#version 120
void main()
{
    float scale(float x);
    gl_FragColor = vec4(scale(0.5));
}
float scale(float x) { return x * 2.0; }
