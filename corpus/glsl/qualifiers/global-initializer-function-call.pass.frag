// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Accepted with the warning glsl-global-initializer: 1.20 drops the sentence, and every driver
// accepts such an initializer in 1.10 too (docs/glsl-disagreements.md).
// 4.3 "Declarations of globals without a qualifier, or with just the const qualifier may include initializers ... Such initializers must have constant type."
// 4.3.2 "Constructors may be used in such expressions, but function calls may not."
float half_of(float x)
{
    return x * 0.5;
}
float g = half_of(1.0);
void main()
{
    gl_FragColor = vec4(g);
}
