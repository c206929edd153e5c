// [config]
// expect_result: fail
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 6.1: "If a built-in function is redeclared in a shader (i.e. a prototype is visible) before a call to it, then the linker will only attempt to resolve that call within the set shaders that are linked with it."
float sin(float x);
void main()
{
    gl_FragColor = vec4(sin(0.5));
}
