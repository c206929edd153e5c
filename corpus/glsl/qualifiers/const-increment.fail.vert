// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.2 "It is an error to write to a const variable outside of its declaration, so they must be initialized when declared."
// 4.3.2 "Any variables qualified as constant are read-only variables for that shader."
#version 110
void main()
{
    const int i = 0;
    i++;
    gl_Position = vec4(float(i));
}
