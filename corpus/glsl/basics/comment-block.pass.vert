// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.4 "Comments are delimited by /* and */, or by // and a new-line."
#version 110
/* a block comment
   float x = ; is not compiled
*/
void main()
{
    gl_Position = /* inline */ vec4(0.0);
}
