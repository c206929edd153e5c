// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "After processing this directive (including its new-line), the implementation will behave as if it is compiling at line number line+1 and source string number source-string-number."
// 3.3 "#error will cause the implementation to put a diagnostic message into the shader's information log ... The implementation must then consider the shader to be ill-formed."
#line 20 7
#if __FILE__ == 7
#error __FILE__ is 7
#endif
void main()
{
    gl_FragColor = vec4(0.0);
}
