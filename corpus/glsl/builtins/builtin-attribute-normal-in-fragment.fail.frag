// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.3: the built-in attributes "can be used from within a vertex shader"
void main()
{
    gl_FragColor = vec4(gl_Normal, 1.0);
}
