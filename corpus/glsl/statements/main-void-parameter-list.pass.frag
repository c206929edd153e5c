// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1: main "takes no arguments, returns no value, and must be declared as type void"; "The idiom "(void)" as a parameter list is provided for convenience."
void main(void)
{
    gl_FragColor = vec4(1.0);
}
