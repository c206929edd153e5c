// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.3: "Expressions for condition-expression must evaluate to a Boolean."
#version 110
void main()
{
    int n = 3;
    do {
        n--;
    } while (n);
    gl_Position = vec4(float(n));
}
