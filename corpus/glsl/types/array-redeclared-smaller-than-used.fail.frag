// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9: an array declared without a size may be re-declared with one; "It is illegal to declare an array with a size, and then later ... index the same array with an integral constant expression greater than or equal to the declared size" (index 3 was used, size 3 is too small)
uniform vec4 colors[];
void main()
{
    gl_FragColor = colors[3];
}
uniform vec4 colors[3];
