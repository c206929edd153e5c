// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.1 lists radians, degrees, sin, cos, tan, asin, acos, atan; sinh (GLSL 1.30) is not a 1.10 built-in
uniform float f;
void main()
{
    gl_Position = vec4(sinh(f));
}
