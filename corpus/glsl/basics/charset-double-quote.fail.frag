// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.1 "The source character set used for the OpenGL shading languages is a subset of ASCII." (letters, digits, _ . + - / * % < > [ ] ( ) { } ^ | & ~ = ! : ; , ? # and white space)
// 3.1 "There are no character or string data types, so no quoting characters are included."
void main()
{
    float x = "1.0";
    gl_FragColor = vec4(x);
}
