// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.4.2: "It is an error to provide extra arguments beyond this last used argument."
uniform vec4 v;
void main()
{
    mat2 m = mat2(v, 1.0);
    gl_Position = vec4(m[0], m[1]);
}
