// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.6 "A fragment shader can not write to a varying variable."
varying vec4 color;
void set(out vec4 c)
{
    c = vec4(1.0);
}
void main()
{
    set(color);
    gl_FragColor = color;
}
