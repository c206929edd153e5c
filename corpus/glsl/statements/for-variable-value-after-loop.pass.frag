// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.3: "Variables modified by the loop-expression maintain their value after the loop is exited, provided they are still in scope."
#version 110
void main()
{
    int i = 0;
    for (; i < 4; i++)
        ;
    gl_FragColor = vec4(float(i));
}
