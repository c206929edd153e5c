// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.7 "Identifiers starting with \"gl_\" are reserved for use by OpenGL, and may not be declared in a shader as either a variable or a function."
void main()
{
    vec4 gl_FragColor = vec4(1.0);
}
