// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.2: gl_FragData is one of "The built-in variables that are accessible from a fragment shader"
void main()
{
    gl_Position = vec4(0.0);
    gl_FragData[0] = vec4(1.0);
}
