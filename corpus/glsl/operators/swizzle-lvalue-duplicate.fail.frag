// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.5: "pos.xx = vec2(3.0, 4.0); // illegal - 'x' used twice"
#version 110
void main()
{
    vec4 pos = vec4(1.0, 2.0, 3.0, 4.0);
    pos.xx = vec2(3.0, 4.0);
    gl_FragColor = pos;
}
