// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.4 "float a, b = 1.5;"
void main()
{
    float a, b = 1.5;
    a = b * 2.0;
    gl_FragColor = vec4(a);
}
