// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.3: "Expressions for condition-expression must evaluate to a Boolean."
#version 110
void main()
{
    float s = 0.0;
    for (int i = 3; i; i--)
        s += 1.0;
    gl_Position = vec4(s);
}
