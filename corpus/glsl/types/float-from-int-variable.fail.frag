// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4 "The OpenGL Shading Language is type safe. There are no implicit conversions between types."
uniform int i;
void main()
{
    float x = 0.0;
    x = i;
    gl_FragColor = vec4(x);
}
