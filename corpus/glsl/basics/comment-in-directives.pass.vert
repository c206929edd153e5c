// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.4 "Comments are delimited by /* and */, or by // and a new-line."
// 3.4 "If a comment resides entirely within a single line, it is treated syntactically as a single space."
#version 110
#define SCALE /* block */ 2.0 // line
#if /* block */ 1 // line
float x = SCALE;
#endif /* block */
void main()
{
    gl_Position = vec4(x);
}
