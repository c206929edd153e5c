// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.3: "attribute vec4 gl_Color;"; 4.3.4: "Attribute variables are read-only as far as the vertex shader is concerned."
void main()
{
    gl_Color = vec4(1.0);
    gl_Position = vec4(0.0);
}
