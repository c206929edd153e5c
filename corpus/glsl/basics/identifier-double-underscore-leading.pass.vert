// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Accepted with the warning glsl-reserved-identifier: the name is reserved, and every driver
// (Mesa, glslang) accepts it (docs/glsl-disagreements.md).
// 3.6 "In addition, all identifiers containing two consecutive underscores (__) are reserved as possible future keywords."
float __scale = 1.0;
void main()
{
    gl_Position = vec4(__scale);
}
