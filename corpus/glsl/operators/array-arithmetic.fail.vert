// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.2: "Array elements are accessed using the array subscript operator ( [ ] ). This is the only operator that operates on arrays."
#version 110
void main()
{
    float a[2];
    float b[2];
    a[0] = 1.0; a[1] = 2.0;
    b[0] = 3.0; b[1] = 4.0;
    float c = (a + b)[0];
    gl_Position = vec4(c);
}
