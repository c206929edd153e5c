// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1: "The idiom "(void)" as a parameter list is provided for convenience."; 9: "function_call_header_no_parameters: function_call_header VOID"
#version 110
float one(void)
{
    return 1.0;
}
void main()
{
    gl_FragColor = vec4(one(), one(void), 0.0, 1.0);
}
