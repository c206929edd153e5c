// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "It will compile only if expression and lvalue have the same type."
#version 110
void main()
{
    int i;
    i = 2.0;
    gl_FragColor = vec4(float(i));
}
