// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.4: "The discard keyword is only allowed within fragment shaders." (any function of a fragment shader)
void kill(float a)
{
    if (a < 0.5)
        discard;
}
void main()
{
    kill(gl_Color.a);
    gl_FragColor = gl_Color;
}
