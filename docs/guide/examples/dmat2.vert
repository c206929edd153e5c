// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 1.1 "3.6 ... clarified that the listed keywords and reserved words are the only ones." (dmat2 is reserved only in later versions)
#version 110
float dmat2 = 1.0;
void main()
{
    gl_Position = vec4(dmat2);
}
