// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.6 "The following are the keywords reserved for future use. Using them will result in an error"
// 9 "Grammar Note: No 'switch'. Switch statements not supported."
#version 110
uniform int mode;
void main()
{
    float x = 0.0;
    switch (mode) {
    default:
        x = 1.0;
    }
    gl_Position = vec4(x);
}
