// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 1.1 "3.6 ... clarified that the listed keywords and reserved words are the only ones." (centroid, flat, smooth, noperspective are not keywords of 1.10)
#version 110
float centroid = 1.0;
float flat = 2.0;
float smooth = 3.0;
float noperspective = 4.0;
void main()
{
    gl_Position = vec4(centroid, flat, smooth, noperspective);
}
