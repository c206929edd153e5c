// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.3 "octal-constant : 0 / octal-constant octal-digit ... octal-digit : one of 01234567" (010 is eight, not ten)
// 4.1.9 "It is illegal to declare an array with a size, and then later (in the same shader) index the same array with an integral constant expression greater than or equal to the declared size."
#version 110
void main()
{
    float a[010];
    a[8] = 1.0;
    gl_Position = vec4(a[8]);
}
