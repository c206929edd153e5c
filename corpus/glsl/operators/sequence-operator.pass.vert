// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.9: "The sequence ( , ) operator that operates on expressions by returning the type and value of the right-most expression"
#version 110
uniform float a;
void main()
{
    float x;
    float y = (x = a, true, 2.0 * a);
    gl_Position = vec4(x, y, 0.0, 1.0);
}
