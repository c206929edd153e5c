// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 4.2 (scoping of compound statements): "However, a nested scope can override an outer scope's declaration of a particular variable name."
#version 110
float a = 1.0;
void main()
{
    float a = 2.0;
    {
        float a = 3.0;
        gl_FragColor = vec4(a);
    }
}
