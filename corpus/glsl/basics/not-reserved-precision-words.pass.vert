// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 1.1 "3.6 ... clarified that the listed keywords and reserved words are the only ones."
// 3.6 "The following are the keywords reserved for future use. Using them will result in an error" (highp, mediump, lowp and precision are not in the 1.10 lists)
#version 110
float highp = 1.0;
float mediump = 2.0;
float lowp = 3.0;
float precision = 4.0;
void main()
{
    gl_Position = vec4(highp, mediump, lowp, precision);
}
