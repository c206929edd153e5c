// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Accepted with the warning glsl-global-initializer: 1.20 drops the sentence, and every driver
// accepts such an initializer in 1.10 too (docs/glsl-disagreements.md).
// 4.3 "Declarations of globals without a qualifier, or with just the const qualifier may include initializers ... Such initializers must have constant type."
#version 110
uniform float u;
float g = u;
void main()
{
    gl_Position = vec4(g);
}
