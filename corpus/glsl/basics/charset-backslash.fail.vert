// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.1 "The source character set used for the OpenGL shading languages is a subset of ASCII." (letters, digits, _ . + - / * % < > [ ] ( ) { } ^ | & ~ = ! : ; , ? # and white space) (no backslash, hence no line continuation)
#version 110
void main()
{
    float x = 1.0 \
        + 2.0;
    gl_Position = vec4(x);
}
