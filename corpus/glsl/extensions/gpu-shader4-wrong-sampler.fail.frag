// [config]
// expect_result: fail
// glsl_version: 1.20
// require_extensions: GL_EXT_gpu_shader4
// [end config]
// EXT_gpu_shader4 8.7: "gvec4 texelFetch2D(gsampler2D sampler, ivec2 coord, int lod)" (a 2D array sampler matches no overload)
#version 120
#extension GL_EXT_gpu_shader4 : require
uniform sampler2DArray layers;
void main()
{
    gl_FragColor = texelFetch2D(layers, ivec2(0), 0);
}
