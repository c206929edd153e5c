// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 1.1 "3.6 ... clarified that the listed keywords and reserved words are the only ones."
#version 110
float layout = 1.0;
float location = 2.0;
float shared = 3.0;
float std140 = 4.0;
float buffer = 5.0;
float row_major = 6.0;
void main()
{
    gl_Position = vec4(layout, location, shared, std140) * buffer * row_major;
}
