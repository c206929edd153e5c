// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.9 "It is illegal to declare an array with a size, and then later (in the same shader) index the same array with an integral constant expression greater than or equal to the declared size."
// 4.1.9 "Undefined behavior results from indexing an array with a non-constant expression that's greater than or equal to the array's size or less than 0." (not a compile error)
#version 110
uniform int i;
void main()
{
    const int last = 2;
    float a[3];
    a[0] = 0.0;
    a[last] = 2.0;
    a[i] = 1.0;
    gl_Position = vec4(a[0], a[last], a[i], 1.0);
}
