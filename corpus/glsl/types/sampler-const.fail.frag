// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.7 "They can only be declared as function parameters or uniforms"
uniform sampler2D tex;
const sampler2D other = tex;
void main()
{
    gl_FragColor = texture2D(other, vec2(0.5));
}
