// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 1.1 "3.6 ... clarified that the listed keywords and reserved words are the only ones." (type names of later versions are plain identifiers in 1.10)
#version 110
float mat2x3 = 1.0;
float mat4x4 = 1.0;
float isampler2D = 1.0;
float usampler2D = 1.0;
float sampler1DArray = 1.0;
float samplerCubeShadow = 1.0;
float samplerBuffer = 1.0;
float sampler2DMS = 1.0;
float image2D = 1.0;
float atomic_uint = 1.0;
void main()
{
    gl_Position = vec4(mat2x3 * mat4x4 * isampler2D * usampler2D * sampler1DArray
                       * samplerCubeShadow * samplerBuffer * sampler2DMS * image2D * atomic_uint);
}
