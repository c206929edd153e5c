// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "Each directive is terminated by a new-line." (the rest of the line belongs to the directive)
#define ONE 1.0 float x = ONE;
void main()
{
    gl_Position = vec4(x);
}
