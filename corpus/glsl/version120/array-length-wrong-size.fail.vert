// [config]
// expect_result: fail
// glsl_version: 1.20
// [end config]
// 1.20 5.4.4: "There must be exactly the same number of arguments as the size of the array being constructed."
#version 120
void main()
{
    float a[3] = float[3](1.0, 2.0);
    gl_Position = vec4(a[0]);
}
