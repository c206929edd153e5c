// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.4: "const int gl_MaxDrawBuffers = 1;" (an int; 5.8 requires the same type for assignment)
void main()
{
    float n = gl_MaxDrawBuffers;
    gl_FragColor = vec4(n);
}
