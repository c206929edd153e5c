// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "Preprocessing does not change the number or relative location of new-lines in a source string."
// 3.3 "__LINE__ will substitute a decimal integer constant that is one more than the number of preceding new-lines in the current source string."
// 3.3 "#error will cause the implementation to put a diagnostic message into the shader's information log ... The implementation must then consider the shader to be ill-formed."
#version 110
/* a block comment
   spanning
   several lines */
#if __LINE__ == 12
#error new-lines inside the comment were counted
#endif
void main()
{
    gl_Position = vec4(0.0);
}
