// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.2: "Any expression whose type evaluates to a Boolean can be used as the conditional expression"
#version 110
uniform float f;
void main()
{
    vec4 c = vec4(0.0);
    if (f)
        c.x = 1.0;
    gl_FragColor = c;
}
