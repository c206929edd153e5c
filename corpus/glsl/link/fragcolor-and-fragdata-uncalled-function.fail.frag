// [config]
// expect_result: fail
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 7.2: "A shader contains a static assignment to a variable x if, after pre-processing, the shader contains a statement that would write to x, whether or not run-time flow of control will cause that statement to be executed."
void unused()
{
    gl_FragData[0] = vec4(0.0);
}
void main()
{
    gl_FragColor = vec4(1.0);
}
