// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "or one can be a scalar float and the other a float vector or matrix, or one can be a scalar integer and the other an integer vector" (an int scalar with a float vector is neither)
void main()
{
    vec2 v = vec2(4.0);
    v /= 2;
    gl_Position = vec4(v, 0.0, 1.0);
}
