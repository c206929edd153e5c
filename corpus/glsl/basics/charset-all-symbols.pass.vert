// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.1 "The source character set used for the OpenGL shading languages is a subset of ASCII." (letters, digits, _ . + - / * % < > [ ] ( ) { } ^ | & ~ = ! : ; , ? # and white space)
#version 110
// Every symbol of the character set; % ^ | & ~ are reserved operators in the
// language, so they appear in a preprocessor expression only.
#if (7 % 4) != 3 || (6 ^ 3) != 5 || (6 | 3) != 7 || (6 & 3) != 2 || ~0 != -1
#error
#endif
struct S { float f; };
void main()
{
    S s = S(1.0);
    float a[2];
    a[0] = s.f;
    a[1] = (a[0] + 1.0 - 2.0) * 3.0 / 4.0;
    bool b = !(a[0] < a[1]) && (a[0] > 0.0) || a[1] <= 0.0 || a[1] >= 0.0;
    float c = b ? 1.0 : 0.0;
    gl_Position = vec4(c, a[0], a[1], 1.0);
}
