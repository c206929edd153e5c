// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: "The bias parameter is not accepted in a vertex shader."
uniform sampler2DShadow s;
void main()
{
    gl_Position = shadow2D(s, gl_MultiTexCoord0.xyz, 0.5);
}
