// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4 "The OpenGL Shading Language is type safe. There are no implicit conversions between types."
uniform float f;
void main()
{
    int i = 0;
    i = f;
    gl_FragColor = vec4(float(i));
}
