// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "It is also illegal to index an array with a negative constant expression."
const int one = 1;
void main()
{
    float a[3];
    a[0] = 1.0;
    gl_FragColor = vec4(a[one - 2]);
}
