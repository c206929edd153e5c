// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "the l-value and expression must satisfy the semantic requirements of both op and equals"; 5.9: "The two operands must be the same type"
#version 110
void main()
{
    int i = 1;
    i += 1.0;
    gl_FragColor = vec4(float(i));
}
