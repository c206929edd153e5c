// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: "In all functions below, the bias parameter is optional for fragment shaders. The bias parameter is not accepted in a vertex shader."
uniform sampler2D s;
void main()
{
    gl_Position = texture2D(s, gl_MultiTexCoord0.xy, 1.0);
}
