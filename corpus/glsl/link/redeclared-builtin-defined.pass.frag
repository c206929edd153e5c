// [config]
// expect_result: pass
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 6.1: "A shader can redefine built-in functions. If a built-in function is redeclared in a shader ... the linker will only attempt to resolve that call within the set shaders that are linked with it."
#version 110
float sin(float x);
void main()
{
    gl_FragColor = vec4(sin(0.5));
}
float sin(float x)
{
    return x - x * x * x / 6.0;
}
