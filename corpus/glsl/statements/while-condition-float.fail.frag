// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.3: "Expressions for condition-expression must evaluate to a Boolean."
#version 110
void main()
{
    float x = 1.0;
    while (x)
        x -= 0.5;
    gl_FragColor = vec4(x);
}
