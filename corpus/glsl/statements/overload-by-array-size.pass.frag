// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1: overloading is allowed "as long as the argument list types differ"; "an exact match for the function's signature is sought. This includes exact match of array size as well."
float sum(float a[2]) { return a[0] + a[1]; }
float sum(float a[3]) { return a[0] + a[1] + a[2]; }
void main()
{
    float p[2];
    float q[3];
    p[0] = 1.0; p[1] = 2.0;
    q[0] = 1.0; q[1] = 2.0; q[2] = 3.0;
    gl_FragColor = vec4(sum(p), sum(q), 0.0, 1.0);
}
