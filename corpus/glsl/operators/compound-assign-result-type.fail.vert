// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "the l-value and expression must satisfy the semantic requirements of both op and equals (=)." (float * vec3 is a vec3, which cannot be assigned to a float)
#version 110
void main()
{
    float f = 1.0;
    f *= vec3(2.0);
    gl_Position = vec4(f);
}
