// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.1: "There is no address-of operator nor a dereference operator."
#version 110
void main()
{
    float f = 1.0;
    float g = &f;
    gl_FragColor = vec4(g);
}
