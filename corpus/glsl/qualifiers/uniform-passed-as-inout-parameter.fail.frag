// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.5 "All uniform variables are read-only and are initialized either directly by an application via API commands, or indirectly by OpenGL."
uniform float u;
void bump(inout float x)
{
    x += 1.0;
}
void main()
{
    bump(u);
    gl_FragColor = vec4(u);
}
