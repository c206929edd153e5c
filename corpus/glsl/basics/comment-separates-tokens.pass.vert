// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.4 "If a comment resides entirely within a single line, it is treated syntactically as a single space."
#version 110
void/**/main()
{
    float/* a comment */x = 1.0;
    gl_Position = vec4/**/(x);
}
