// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.10 / 5.9: component-wise binary operations require "The two operands must be the same type"
#version 110
uniform mat2 a;
uniform mat3 b;
void main()
{
    mat3 c = b + a;
    gl_FragColor = vec4(c[0], 1.0);
}
