// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3 "Global variables can only use the qualifiers const, attribute, uniform, or varying. Only one may be specified."
uniform uniform float u;
void main()
{
    gl_FragColor = vec4(0.0);
}
