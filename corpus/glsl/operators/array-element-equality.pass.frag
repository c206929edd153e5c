// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.9: "Subscripted array names" are expressions and the equality operators "operate on all types except arrays"
#version 110
void main()
{
    float a[2];
    float b[2];
    a[0] = 1.0; a[1] = 2.0;
    b[0] = 1.0; b[1] = 2.0;
    bool e = a[0] == b[0] && a[1] != b[1];
    gl_FragColor = vec4(float(e));
}
