// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "The two operands must be the same type"; 5.10: component-wise operations need operands of the same size
#version 110
uniform vec3 a;
uniform vec2 b;
void main()
{
    vec3 c = a + b;
    gl_Position = vec4(c, 1.0);
}
