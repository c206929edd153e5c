// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.2: "Conditional control flow in the shading language is done by either if, or if-else" and "Conditionals can be nested."
#version 110
uniform int k;
void main()
{
    float f;
    if (k == 0)
        f = 1.0;
    else if (k == 1)
        f = 2.0;
    else {
        if (k > 5)
            f = 3.0;
        else
            f = 4.0;
    }
    gl_Position = vec4(f);
}
