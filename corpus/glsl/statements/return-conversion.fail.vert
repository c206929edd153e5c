// [config]
// expect_result: fail
// glsl_version: 1.20
// [end config]
// 1.20 4.1.10: implicit conversions "are done only as indicated by other sections of this specification"; 6.1 and 6.4 indicate none for a return value (1.10 has no implicit conversions at all)
#version 120
float half_of(int i)
{
    return i / 2;
}
void main()
{
    gl_Position = vec4(half_of(3));
}
