// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.2 "If it is declared in a while test or a for statement, then it is scoped to the end of the following sub-statement."
// 9 "condition: expression / fully_specified_type IDENTIFIER EQUAL initializer"
#version 110
uniform float limit;
void main()
{
    float x = 0.0;
    while (bool more = x < limit)
        x += 1.0;
    bool more = false;
    gl_Position = vec4(x);
}
