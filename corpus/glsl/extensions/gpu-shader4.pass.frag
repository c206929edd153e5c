// [config]
// expect_result: pass
// glsl_version: 1.20
// require_extensions: GL_EXT_gpu_shader4
// [end config]
// EXT_gpu_shader4: unsigned integers, integer samplers, texelFetch2D, textureSize2D, flat varyings, "varying out" fragment outputs, bitwise operators and %
#version 120
#extension GL_EXT_gpu_shader4 : require
uniform isampler2D labels;
uniform usampler2D masks;
flat varying int layer;
varying out vec4 color;
void main()
{
    ivec2 size = textureSize2D(labels, 0);
    int label = texelFetch2D(labels, ivec2(gl_FragCoord.xy) % size, 0).r;
    unsigned int mask = texelFetch2D(masks, ivec2(0, 0), 0).r;
    color = vec4(float(label ^ layer), float(mask & 0xFFu), float(gl_PrimitiveID), 1.0);
}
