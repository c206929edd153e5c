// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 1.1 "3.6 ... clarified that the listed keywords and reserved words are the only ones."
// 4.3 "Variable declarations may have one or more qualifiers" (const, attribute, uniform, varying, in, out, inout only)
uniform highp vec4 color;
void main()
{
    gl_FragColor = color;
}
