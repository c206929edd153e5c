// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 4.1.9: "Only one-dimensional arrays may be declared."; 5.2: an element of a float array is a float, which cannot be subscripted
uniform float w[2];
void main()
{
    gl_Position = vec4(w[0][0]);
}
