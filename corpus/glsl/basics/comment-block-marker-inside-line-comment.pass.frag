// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.4 "The begin comment delimiters (/* or //) are not recognized as comment delimiters inside of a comment, hence comments cannot be nested."
// /* this is not the start of a block comment
float x = 1.0;
void main()
{
    gl_FragColor = vec4(x);
}
