// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.2 "If it is declared in a while test or a for statement, then it is scoped to the end of the following sub-statement."
#version 110
void main()
{
    float sum = 0.0;
    for (int i = 0; i < 4; ++i)
        sum += 1.0;
    for (int i = 0; i < 2; ++i)
        sum += 1.0;
    float i = sum;
    gl_Position = vec4(i);
}
