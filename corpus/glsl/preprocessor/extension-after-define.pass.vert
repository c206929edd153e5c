// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "If nothing is said, the granularity is a shader ... and the extension directives must occur before any non-preprocessor tokens." (only non-preprocessor tokens must not precede it)
#version 110
#define SCALE 2.0
#extension all : warn
void main()
{
    gl_Position = vec4(SCALE);
}
