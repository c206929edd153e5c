// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 1.1 "3.6 ... clarified that the listed keywords and reserved words are the only ones."
// 4.3 qualifiers of 1.10: const, attribute, uniform, varying, in, out, inout
#version 110
invariant gl_Position;
void main()
{
    gl_Position = vec4(0.0);
}
