// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.5 "All uniform variables are read-only and are initialized either directly by an application via API commands, or indirectly by OpenGL."
uniform vec4 colors[2];
void main()
{
    colors[0] = vec4(1.0);
    gl_FragColor = colors[0];
}
