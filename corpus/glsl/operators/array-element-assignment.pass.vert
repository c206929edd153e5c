// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.8: "l-values dereferenced with the array subscript operator ( [ ] ) are all l-values."
#version 110
void main()
{
    float a[2];
    float b[2];
    b[0] = 1.0; b[1] = 2.0;
    a[0] = b[0];
    a[1] = b[1];
    gl_Position = vec4(a[0], a[1], 0.0, 1.0);
}
