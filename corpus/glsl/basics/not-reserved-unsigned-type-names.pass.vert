// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 1.1 "3.6 ... clarified that the listed keywords and reserved words are the only ones." (uint and uvecN are not keywords of 1.10; unsigned is)
#version 110
float uint = 1.0;
float uvec2 = 2.0;
float uvec3 = 3.0;
float uvec4 = 4.0;
void main()
{
    gl_Position = vec4(uint, uvec2, uvec3, uvec4);
}
