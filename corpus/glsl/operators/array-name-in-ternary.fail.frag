// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: the ternary "second and third expressions must be the same type, but can be of any type other than an array."
uniform bool p;
void main()
{
    float a[2];
    float b[2];
    a[0] = 1.0; a[1] = 2.0;
    b[0] = 3.0; b[1] = 4.0;
    float c = (p ? a : b)[0];
    gl_FragColor = vec4(c);
}
