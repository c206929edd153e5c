// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3 "Local variables can only use the qualifier const."
void main()
{
    float x = 0.0;
    for (int i = 0; i < 2; ++i) {
        const float step = 0.25;
        x += step;
    }
    gl_FragColor = vec4(x);
}
