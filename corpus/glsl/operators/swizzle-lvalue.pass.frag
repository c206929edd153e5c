// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.5: "pos.xw = vec2(5.0, 6.0); // pos = (5.0, 2.0, 3.0, 6.0)" and "pos.wx = vec2(7.0, 8.0);"
void main()
{
    vec4 pos = vec4(1.0, 2.0, 3.0, 4.0);
    pos.xw = vec2(5.0, 6.0);
    pos.wx = vec2(7.0, 8.0);
    pos.b = 0.5;
    gl_FragColor = pos;
}
