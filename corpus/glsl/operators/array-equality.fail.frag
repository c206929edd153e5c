// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "The equality operators equal (==), and not equal (!=) operate on all types except arrays."
void main()
{
    float a[2];
    float b[2];
    a[0] = 1.0; a[1] = 2.0;
    b[0] = 1.0; b[1] = 2.0;
    bool e = a == b;
    gl_FragColor = vec4(float(e));
}
