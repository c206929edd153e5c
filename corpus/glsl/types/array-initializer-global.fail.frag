// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "There is no mechanism for initializing arrays at declaration time from within a shader."
const float a[2] = float[2](1.0, 2.0);
void main()
{
    gl_FragColor = vec4(a[0]);
}
