// [config]
// expect_result: fail
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 6.1: a prototype declares a function; the call must be resolved to a definition in the linked shaders
vec4 shade(vec2 uv);
void main()
{
    gl_FragColor = shade(gl_TexCoord[0].xy);
}
