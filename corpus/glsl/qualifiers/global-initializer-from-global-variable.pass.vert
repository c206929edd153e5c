// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Accepted with the warning glsl-global-initializer: 1.20 drops the sentence, and every driver
// accepts such an initializer in 1.10 too (docs/glsl-disagreements.md).
// 4.3 "Declarations of globals without a qualifier, or with just the const qualifier may include initializers ... Such initializers must have constant type." (an unqualified global is not constant)
#version 110
float a = 1.0;
float b = a * 2.0;
void main()
{
    gl_Position = vec4(b);
}
