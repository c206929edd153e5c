// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.6 "The following are the keywords reserved for future use. Using them will result in an error"
// 9 "Grammar Note: No 'enum', or 'typedef'."
#version 110
typedef vec4 color;
void main()
{
    gl_Position = vec4(0.0);
}
