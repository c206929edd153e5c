// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "If nothing is said, the granularity is a shader ... and the extension directives must occur before any non-preprocessor tokens."
void helper()
{
}
#extension all : warn
void main()
{
    gl_FragColor = vec4(0.0);
}
