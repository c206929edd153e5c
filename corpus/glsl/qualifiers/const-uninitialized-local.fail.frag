// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.2 "It is an error to write to a const variable outside of its declaration, so they must be initialized when declared."
void main()
{
    const vec4 c;
    gl_FragColor = c;
}
