// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "#pragma optimize(on) / #pragma optimize(off) ... It can only be used outside function definitions." (same for debug)
void main()
{
#pragma debug(on)
    gl_FragColor = vec4(0.0);
}
