// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "The number sign (#) on a line by itself is ignored."
#version 110
#
   #
void main()
{
    gl_Position = vec4(0.0);
}
