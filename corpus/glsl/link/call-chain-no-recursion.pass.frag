// [config]
// expect_result: pass
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 6.1.1: recursion is "any function appearing more than once at any one time in the run-time stack"; repeated non-nested calls are fine
#version 110
float sq(float x)
{
    return x * x;
}
float quad(float x)
{
    return sq(sq(x));
}
void main()
{
    gl_FragColor = vec4(quad(0.5) + sq(0.5) + quad(sq(0.2)));
}
