// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]
// 1.20 4.1.4: "floating-suffix: one of f F"
#version 120
void main()
{
    gl_FragColor = vec4(0.5f, 1.0F, 2e-1f, 1.f);
}
