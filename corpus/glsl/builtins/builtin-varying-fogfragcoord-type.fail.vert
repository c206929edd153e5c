// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.6: "varying float gl_FogFragCoord;"
#version 110
void main()
{
    gl_Position = ftransform();
    gl_FogFragCoord = gl_Position;
}
