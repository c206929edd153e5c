// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.6: "Behavior is undefined when accessing a component outside the bounds of a matrix (e.g., component [3][3] of a mat3)." (undefined behaviour, not a compile error)
#version 110
uniform mat3 m;
void main()
{
    gl_Position = vec4(m[3][3]);
}
