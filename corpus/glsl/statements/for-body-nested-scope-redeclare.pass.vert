// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 4.2: "a nested scope can override an outer scope's declaration of a particular variable name." (a compound statement inside the loop body opens a new scope)
#version 110
void main()
{
    float s = 0.0;
    for (int i = 0; i < 2; i++) {
        {
            int i = 5;
            s += float(i);
        }
    }
    gl_Position = vec4(s);
}
