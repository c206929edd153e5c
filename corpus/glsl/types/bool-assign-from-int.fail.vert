// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.2 "The right side of the assignment operator ( = ) can be any expression whose type is bool."
// 4 "The OpenGL Shading Language is type safe. There are no implicit conversions between types."
uniform int i;
void main()
{
    bool b = false;
    b = i;
    gl_Position = vec4(0.0);
}
