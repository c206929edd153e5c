// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4 "The OpenGL Shading Language is type safe. There are no implicit conversions between types."
// 4.1.3 "Integers are declared and optionally initialized with integer expressions"
uniform int u;
void main()
{
    int i = u * 2 + 1;
    int j = int(2.5);
    gl_FragColor = vec4(float(i + j));
}
