// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.8: "The arithmetic assignments add into (+=), subtract from (-=), multiply into (*=), and divide into (/=)."
uniform int a;
uniform float f;
void main()
{
    int c = 7;
    c += a;
    c -= 1;
    c *= a;
    c /= 2;
    float g = f;
    g += 1.0;
    g -= f;
    g *= 2.0;
    g /= 3.0;
    gl_Position = vec4(float(c), g, 0.0, 1.0);
}
