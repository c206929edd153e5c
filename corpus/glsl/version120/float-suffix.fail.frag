// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 1.10 4.1.4 has no floating-suffix: "1.0f" is not a 1.10 floating-point constant
#version 110
void main()
{
    gl_FragColor = vec4(0.5f);
}
