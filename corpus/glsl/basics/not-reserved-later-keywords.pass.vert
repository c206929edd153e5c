// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 1.1 "3.6 ... clarified that the listed keywords and reserved words are the only ones." (keywords of later versions are plain identifiers in 1.10)
#version 110
float patch = 1.0;
float sample = 1.0;
float subroutine = 1.0;
float coherent = 1.0;
float restrict = 1.0;
float readonly = 1.0;
float writeonly = 1.0;
float resource = 1.0;
float superp = 1.0;
void main()
{
    gl_Position = vec4(patch * sample * subroutine * coherent * restrict * readonly * writeonly
                       * resource * superp);
}
