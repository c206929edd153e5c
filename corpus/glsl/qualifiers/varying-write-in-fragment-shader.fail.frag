// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.6 "A fragment shader can not write to a varying variable."
varying vec4 color;
void main()
{
    color = vec4(1.0);
    gl_FragColor = color;
}
