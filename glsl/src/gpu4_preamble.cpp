// The EXT_gpu_shader4 and EXT_texture_array built-ins as GLSL 1.30 functions: a table of
// {return, name, parameters, 1.30 expression} rows, expanded over the sampler prefixes and stages.
#include "gpu4_preamble.h"

#include <array>
#include <cstddef>
#include <string>

namespace arbiter::glsl {
namespace {

// Which overloads a row stands for. A row's text uses {g} for the sampler prefix, {R} for the
// matching vec4/ivec4/uvec4 and {T} for the genType.
enum class Expand {
  AsWritten,   // the row as written
  Sampler,     // float, int and uint samplers (int and uint with gpu_shader4 only)
  IntSampler,  // int and uint samplers: 1.30 has the float one under the same name
  GenType,     // float, vec2, vec3, vec4
};

// Row flags. kBias: also a fragment-only overload with a trailing `float bias`, passed as {bias}.
constexpr unsigned kBias = 1;
// 1.10, 8.7: "allowed only in a vertex shader"; gpu_shader4 removes the sentence.
constexpr unsigned kVertexLod = 2;
// Needs ARB_texture_rectangle.
constexpr unsigned kRect = 4;
// A depth comparison: 1.30 returns the float r, the extensions a vec4 of the texture's
// DEPTH_TEXTURE_MODE (GL 2.0, 3.8.14), whose initial value LUMINANCE gives (r, r, r, 1).
constexpr unsigned kShadow = 8;

struct Row {
  std::string_view ret;
  std::string_view name;
  std::string_view params;
  std::string_view body;  // the value returned
  Expand expand = Expand::AsWritten;
  unsigned flags = 0;
};

// EXT_texture_array's functions; EXT_gpu_shader4 lists them too, and overloads the non-shadow
// ones for integer samplers.
constexpr Row kTextureArray[] = {
    {"{R}", "texture1DArray", "{g}sampler1DArray s, vec2 coord", "texture(s, coord{bias})",
     Expand::Sampler, kBias},
    {"{R}", "texture1DArrayLod", "{g}sampler1DArray s, vec2 coord, float lod",
     "textureLod(s, coord, lod)", Expand::Sampler, kVertexLod},
    {"{R}", "texture2DArray", "{g}sampler2DArray s, vec3 coord", "texture(s, coord{bias})",
     Expand::Sampler, kBias},
    {"{R}", "texture2DArrayLod", "{g}sampler2DArray s, vec3 coord, float lod",
     "textureLod(s, coord, lod)", Expand::Sampler, kVertexLod},
    {"vec4", "shadow1DArray", "sampler1DArrayShadow s, vec3 coord", "texture(s, coord{bias})",
     Expand::AsWritten, kShadow | kBias},
    {"vec4", "shadow1DArrayLod", "sampler1DArrayShadow s, vec3 coord, float lod",
     "textureLod(s, coord, lod)", Expand::AsWritten, kShadow | kVertexLod},
    {"vec4", "shadow2DArray", "sampler2DArrayShadow s, vec4 coord", "texture(s, coord)",
     Expand::AsWritten, kShadow},
};

// The rest of EXT_gpu_shader4, in the order of its 8.7 and 8.3 additions.
//
// An offset must be a constant expression in 1.30's lookups, and a parameter is not one, so the
// *Offset bodies apply it themselves: exactly for texel fetches and rectangle textures (added
// to the texel coordinates), as offset / size of the base level for the others (exact when the
// base level is the one sampled). The Proj forms divide by q first, which is what Proj means.
constexpr Row kGpuShader4[] = {
    // "Integer and unsigned integer functions of all the texture lookup functions described in
    // this section": the 1.10 lookups.
    {"{R}", "texture1D", "{g}sampler1D s, float coord", "texture(s, coord{bias})",
     Expand::IntSampler, kBias},
    {"{R}", "texture1DProj", "{g}sampler1D s, vec2 coord", "textureProj(s, coord{bias})",
     Expand::IntSampler, kBias},
    {"{R}", "texture1DProj", "{g}sampler1D s, vec4 coord", "textureProj(s, coord{bias})",
     Expand::IntSampler, kBias},
    {"{R}", "texture1DLod", "{g}sampler1D s, float coord, float lod", "textureLod(s, coord, lod)",
     Expand::IntSampler},
    {"{R}", "texture1DProjLod", "{g}sampler1D s, vec2 coord, float lod",
     "textureProjLod(s, coord, lod)", Expand::IntSampler},
    {"{R}", "texture1DProjLod", "{g}sampler1D s, vec4 coord, float lod",
     "textureProjLod(s, coord, lod)", Expand::IntSampler},
    {"{R}", "texture2D", "{g}sampler2D s, vec2 coord", "texture(s, coord{bias})",
     Expand::IntSampler, kBias},
    {"{R}", "texture2DProj", "{g}sampler2D s, vec3 coord", "textureProj(s, coord{bias})",
     Expand::IntSampler, kBias},
    {"{R}", "texture2DProj", "{g}sampler2D s, vec4 coord", "textureProj(s, coord{bias})",
     Expand::IntSampler, kBias},
    {"{R}", "texture2DLod", "{g}sampler2D s, vec2 coord, float lod", "textureLod(s, coord, lod)",
     Expand::IntSampler},
    {"{R}", "texture2DProjLod", "{g}sampler2D s, vec3 coord, float lod",
     "textureProjLod(s, coord, lod)", Expand::IntSampler},
    {"{R}", "texture2DProjLod", "{g}sampler2D s, vec4 coord, float lod",
     "textureProjLod(s, coord, lod)", Expand::IntSampler},
    {"{R}", "texture3D", "{g}sampler3D s, vec3 coord", "texture(s, coord{bias})",
     Expand::IntSampler, kBias},
    {"{R}", "texture3DProj", "{g}sampler3D s, vec4 coord", "textureProj(s, coord{bias})",
     Expand::IntSampler, kBias},
    {"{R}", "texture3DLod", "{g}sampler3D s, vec3 coord, float lod", "textureLod(s, coord, lod)",
     Expand::IntSampler},
    {"{R}", "texture3DProjLod", "{g}sampler3D s, vec4 coord, float lod",
     "textureProjLod(s, coord, lod)", Expand::IntSampler},
    {"{R}", "textureCube", "{g}samplerCube s, vec3 coord", "texture(s, coord{bias})",
     Expand::IntSampler, kBias},
    {"{R}", "textureCubeLod", "{g}samplerCube s, vec3 coord, float lod",
     "textureLod(s, coord, lod)", Expand::IntSampler},

    // Texel fetches.
    {"{R}", "texelFetch1D", "{g}sampler1D s, int coord, int lod", "texelFetch(s, coord, lod)",
     Expand::Sampler},
    {"{R}", "texelFetch2D", "{g}sampler2D s, ivec2 coord, int lod", "texelFetch(s, coord, lod)",
     Expand::Sampler},
    {"{R}", "texelFetch3D", "{g}sampler3D s, ivec3 coord, int lod", "texelFetch(s, coord, lod)",
     Expand::Sampler},
    {"vec4", "texelFetch2DRect", "sampler2DRect s, ivec2 coord", "texelFetch(s, coord)",
     Expand::AsWritten, kRect},
    {"{R}", "texelFetch1DArray", "{g}sampler1DArray s, ivec2 coord, int lod",
     "texelFetch(s, coord, lod)", Expand::Sampler},
    {"{R}", "texelFetch2DArray", "{g}sampler2DArray s, ivec3 coord, int lod",
     "texelFetch(s, coord, lod)", Expand::Sampler},
    // 1.30 has the samplerBuffer type but no function taking it: the right type, no value.
    {"vec4", "texelFetchBuffer", "samplerBuffer s, int coord", "vec4(0.0)"},

    // Sizes: int whatever the sampler. A rectangle texture has one level, and 1.30's
    // textureSize takes no lod for it.
    {"int", "textureSizeBuffer", "samplerBuffer s", "0"},
    {"int", "textureSize1D", "{g}sampler1D s, int lod", "textureSize(s, lod)", Expand::Sampler},
    {"ivec2", "textureSize2D", "{g}sampler2D s, int lod", "textureSize(s, lod)", Expand::Sampler},
    {"ivec3", "textureSize3D", "{g}sampler3D s, int lod", "textureSize(s, lod)", Expand::Sampler},
    {"ivec2", "textureSizeCube", "{g}samplerCube s, int lod", "textureSize(s, lod)",
     Expand::Sampler},
    {"ivec2", "textureSize2DRect", "sampler2DRect s, int lod", "textureSize(s)", Expand::AsWritten,
     kRect},
    {"ivec2", "textureSize1DArray", "{g}sampler1DArray s, int lod", "textureSize(s, lod)",
     Expand::Sampler},
    {"ivec3", "textureSize2DArray", "{g}sampler2DArray s, int lod", "textureSize(s, lod)",
     Expand::Sampler},

    {"vec4", "shadowCube", "samplerCubeShadow s, vec4 coord", "texture(s, coord)",
     Expand::AsWritten, kShadow},

    // Explicit gradients. 1.30's ProjGrad also takes derivatives that are already projected.
    {"{R}", "texture1DGrad", "{g}sampler1D s, float coord, float ddx, float ddy",
     "textureGrad(s, coord, ddx, ddy)", Expand::Sampler},
    {"{R}", "texture1DProjGrad", "{g}sampler1D s, vec2 coord, float ddx, float ddy",
     "textureProjGrad(s, coord, ddx, ddy)", Expand::Sampler},
    {"{R}", "texture1DProjGrad", "{g}sampler1D s, vec4 coord, float ddx, float ddy",
     "textureProjGrad(s, coord, ddx, ddy)", Expand::Sampler},
    {"{R}", "texture1DArrayGrad", "{g}sampler1DArray s, vec2 coord, float ddx, float ddy",
     "textureGrad(s, coord, ddx, ddy)", Expand::Sampler},
    {"{R}", "texture2DGrad", "{g}sampler2D s, vec2 coord, vec2 ddx, vec2 ddy",
     "textureGrad(s, coord, ddx, ddy)", Expand::Sampler},
    {"{R}", "texture2DProjGrad", "{g}sampler2D s, vec3 coord, vec2 ddx, vec2 ddy",
     "textureProjGrad(s, coord, ddx, ddy)", Expand::Sampler},
    {"{R}", "texture2DProjGrad", "{g}sampler2D s, vec4 coord, vec2 ddx, vec2 ddy",
     "textureProjGrad(s, coord, ddx, ddy)", Expand::Sampler},
    {"{R}", "texture2DArrayGrad", "{g}sampler2DArray s, vec3 coord, vec2 ddx, vec2 ddy",
     "textureGrad(s, coord, ddx, ddy)", Expand::Sampler},
    {"{R}", "texture3DGrad", "{g}sampler3D s, vec3 coord, vec3 ddx, vec3 ddy",
     "textureGrad(s, coord, ddx, ddy)", Expand::Sampler},
    {"{R}", "texture3DProjGrad", "{g}sampler3D s, vec4 coord, vec3 ddx, vec3 ddy",
     "textureProjGrad(s, coord, ddx, ddy)", Expand::Sampler},
    {"{R}", "textureCubeGrad", "{g}samplerCube s, vec3 coord, vec3 ddx, vec3 ddy",
     "textureGrad(s, coord, ddx, ddy)", Expand::Sampler},
    {"vec4", "shadow1DGrad", "sampler1DShadow s, vec3 coord, float ddx, float ddy",
     "textureGrad(s, coord, ddx, ddy)", Expand::AsWritten, kShadow},
    {"vec4", "shadow1DProjGrad", "sampler1DShadow s, vec4 coord, float ddx, float ddy",
     "textureProjGrad(s, coord, ddx, ddy)", Expand::AsWritten, kShadow},
    {"vec4", "shadow1DArrayGrad", "sampler1DArrayShadow s, vec3 coord, float ddx, float ddy",
     "textureGrad(s, coord, ddx, ddy)", Expand::AsWritten, kShadow},
    {"vec4", "shadow2DGrad", "sampler2DShadow s, vec3 coord, vec2 ddx, vec2 ddy",
     "textureGrad(s, coord, ddx, ddy)", Expand::AsWritten, kShadow},
    {"vec4", "shadow2DProjGrad", "sampler2DShadow s, vec4 coord, vec2 ddx, vec2 ddy",
     "textureProjGrad(s, coord, ddx, ddy)", Expand::AsWritten, kShadow},
    {"vec4", "shadow2DArrayGrad", "sampler2DArrayShadow s, vec4 coord, vec2 ddx, vec2 ddy",
     "textureGrad(s, coord, ddx, ddy)", Expand::AsWritten, kShadow},
    {"vec4", "texture2DRectGrad", "sampler2DRect s, vec2 coord, vec2 ddx, vec2 ddy",
     "textureGrad(s, coord, ddx, ddy)", Expand::AsWritten, kRect},
    {"vec4", "texture2DRectProjGrad", "sampler2DRect s, vec3 coord, vec2 ddx, vec2 ddy",
     "textureProjGrad(s, coord, ddx, ddy)", Expand::AsWritten, kRect},
    {"vec4", "texture2DRectProjGrad", "sampler2DRect s, vec4 coord, vec2 ddx, vec2 ddy",
     "textureProjGrad(s, coord, ddx, ddy)", Expand::AsWritten, kRect},
    {"vec4", "shadow2DRectGrad", "sampler2DRectShadow s, vec3 coord, vec2 ddx, vec2 ddy",
     "textureGrad(s, coord, ddx, ddy)", Expand::AsWritten, kRect | kShadow},
    {"vec4", "shadow2DRectProjGrad", "sampler2DRectShadow s, vec4 coord, vec2 ddx, vec2 ddy",
     "textureProjGrad(s, coord, ddx, ddy)", Expand::AsWritten, kRect | kShadow},
    {"vec4", "shadowCubeGrad", "samplerCubeShadow s, vec4 coord, vec3 ddx, vec3 ddy",
     "textureGrad(s, coord, ddx, ddy)", Expand::AsWritten, kShadow},

    // Offsets. {offN} is the offset in normalised coordinates of an N-dimensional texture
    // ({offNL}: of a layered one).
    {"{R}", "texture1DOffset", "{g}sampler1D s, float coord, int offset",
     "texture(s, coord + {off1}{bias})", Expand::Sampler, kBias},
    {"{R}", "texture1DProjOffset", "{g}sampler1D s, vec2 coord, int offset",
     "texture(s, coord.x / coord.y + {off1}{bias})", Expand::Sampler, kBias},
    {"{R}", "texture1DProjOffset", "{g}sampler1D s, vec4 coord, int offset",
     "texture(s, coord.x / coord.w + {off1}{bias})", Expand::Sampler, kBias},
    {"{R}", "texture1DLodOffset", "{g}sampler1D s, float coord, float lod, int offset",
     "textureLod(s, coord + {off1}, lod)", Expand::Sampler},
    {"{R}", "texture1DProjLodOffset", "{g}sampler1D s, vec2 coord, float lod, int offset",
     "textureLod(s, coord.x / coord.y + {off1}, lod)", Expand::Sampler},
    {"{R}", "texture1DProjLodOffset", "{g}sampler1D s, vec4 coord, float lod, int offset",
     "textureLod(s, coord.x / coord.w + {off1}, lod)", Expand::Sampler},
    {"{R}", "texture2DOffset", "{g}sampler2D s, vec2 coord, ivec2 offset",
     "texture(s, coord + {off2}{bias})", Expand::Sampler, kBias},
    {"{R}", "texture2DProjOffset", "{g}sampler2D s, vec3 coord, ivec2 offset",
     "texture(s, coord.xy / coord.z + {off2}{bias})", Expand::Sampler, kBias},
    {"{R}", "texture2DProjOffset", "{g}sampler2D s, vec4 coord, ivec2 offset",
     "texture(s, coord.xy / coord.w + {off2}{bias})", Expand::Sampler, kBias},
    {"{R}", "texture2DLodOffset", "{g}sampler2D s, vec2 coord, float lod, ivec2 offset",
     "textureLod(s, coord + {off2}, lod)", Expand::Sampler},
    {"{R}", "texture2DProjLodOffset", "{g}sampler2D s, vec3 coord, float lod, ivec2 offset",
     "textureLod(s, coord.xy / coord.z + {off2}, lod)", Expand::Sampler},
    {"{R}", "texture2DProjLodOffset", "{g}sampler2D s, vec4 coord, float lod, ivec2 offset",
     "textureLod(s, coord.xy / coord.w + {off2}, lod)", Expand::Sampler},
    {"{R}", "texture3DOffset", "{g}sampler3D s, vec3 coord, ivec3 offset",
     "texture(s, coord + {off3}{bias})", Expand::Sampler, kBias},
    {"{R}", "texture3DProjOffset", "{g}sampler3D s, vec4 coord, ivec3 offset",
     "texture(s, coord.xyz / coord.w + {off3}{bias})", Expand::Sampler, kBias},
    {"{R}", "texture3DLodOffset", "{g}sampler3D s, vec3 coord, float lod, ivec3 offset",
     "textureLod(s, coord + {off3}, lod)", Expand::Sampler},
    {"{R}", "texture3DProjLodOffset", "{g}sampler3D s, vec4 coord, float lod, ivec3 offset",
     "textureLod(s, coord.xyz / coord.w + {off3}, lod)", Expand::Sampler},
    {"vec4", "shadow1DOffset", "sampler1DShadow s, vec3 coord, int offset",
     "texture(s, vec3(coord.x + {off1}, coord.yz){bias})", Expand::AsWritten, kShadow | kBias},
    {"vec4", "shadow2DOffset", "sampler2DShadow s, vec3 coord, ivec2 offset",
     "texture(s, vec3(coord.xy + {off2}, coord.z){bias})", Expand::AsWritten, kShadow | kBias},
    {"vec4", "shadow1DProjOffset", "sampler1DShadow s, vec4 coord, int offset",
     "texture(s, vec3(coord.x / coord.w + {off1}, coord.yz / coord.w){bias})", Expand::AsWritten,
     kShadow | kBias},
    {"vec4", "shadow2DProjOffset", "sampler2DShadow s, vec4 coord, ivec2 offset",
     "texture(s, vec3(coord.xy / coord.w + {off2}, coord.z / coord.w){bias})", Expand::AsWritten,
     kShadow | kBias},
    {"vec4", "shadow1DLodOffset", "sampler1DShadow s, vec3 coord, float lod, int offset",
     "textureLod(s, vec3(coord.x + {off1}, coord.yz), lod)", Expand::AsWritten, kShadow},
    {"vec4", "shadow2DLodOffset", "sampler2DShadow s, vec3 coord, float lod, ivec2 offset",
     "textureLod(s, vec3(coord.xy + {off2}, coord.z), lod)", Expand::AsWritten, kShadow},
    {"vec4", "shadow1DProjLodOffset", "sampler1DShadow s, vec4 coord, float lod, int offset",
     "textureLod(s, vec3(coord.x / coord.w + {off1}, coord.yz / coord.w), lod)", Expand::AsWritten,
     kShadow},
    {"vec4", "shadow2DProjLodOffset", "sampler2DShadow s, vec4 coord, float lod, ivec2 offset",
     "textureLod(s, vec3(coord.xy / coord.w + {off2}, coord.z / coord.w), lod)", Expand::AsWritten,
     kShadow},
    {"vec4", "texture2DRectOffset", "sampler2DRect s, vec2 coord, ivec2 offset",
     "texture(s, coord + vec2(offset))", Expand::AsWritten, kRect},
    {"vec4", "texture2DRectProjOffset", "sampler2DRect s, vec3 coord, ivec2 offset",
     "texture(s, coord.xy / coord.z + vec2(offset))", Expand::AsWritten, kRect},
    {"vec4", "texture2DRectProjOffset", "sampler2DRect s, vec4 coord, ivec2 offset",
     "texture(s, coord.xy / coord.w + vec2(offset))", Expand::AsWritten, kRect},
    {"vec4", "shadow2DRectOffset", "sampler2DRectShadow s, vec3 coord, ivec2 offset",
     "texture(s, vec3(coord.xy + vec2(offset), coord.z))", Expand::AsWritten, kRect | kShadow},
    {"vec4", "shadow2DRectProjOffset", "sampler2DRectShadow s, vec4 coord, ivec2 offset",
     "texture(s, vec3(coord.xy / coord.w + vec2(offset), coord.z / coord.w))", Expand::AsWritten,
     kRect | kShadow},
    {"{R}", "texelFetch1DOffset", "{g}sampler1D s, int coord, int lod, int offset",
     "texelFetch(s, coord + offset, lod)", Expand::Sampler},
    {"{R}", "texelFetch2DOffset", "{g}sampler2D s, ivec2 coord, int lod, ivec2 offset",
     "texelFetch(s, coord + offset, lod)", Expand::Sampler},
    {"{R}", "texelFetch3DOffset", "{g}sampler3D s, ivec3 coord, int lod, ivec3 offset",
     "texelFetch(s, coord + offset, lod)", Expand::Sampler},
    {"vec4", "texelFetch2DRectOffset", "sampler2DRect s, ivec2 coord, ivec2 offset",
     "texelFetch(s, coord + offset)", Expand::AsWritten, kRect},
    // The offset does not apply to the layer.
    {"{R}", "texelFetch1DArrayOffset", "{g}sampler1DArray s, ivec2 coord, int lod, int offset",
     "texelFetch(s, ivec2(coord.x + offset, coord.y), lod)", Expand::Sampler},
    {"{R}", "texelFetch2DArrayOffset", "{g}sampler2DArray s, ivec3 coord, int lod, ivec2 offset",
     "texelFetch(s, ivec3(coord.xy + offset, coord.z), lod)", Expand::Sampler},
    {"{R}", "texture1DArrayOffset", "{g}sampler1DArray s, vec2 coord, int offset",
     "texture(s, vec2(coord.x + {off1L}, coord.y){bias})", Expand::Sampler, kBias},
    {"{R}", "texture1DArrayLodOffset", "{g}sampler1DArray s, vec2 coord, float lod, int offset",
     "textureLod(s, vec2(coord.x + {off1L}, coord.y), lod)", Expand::Sampler},
    {"{R}", "texture2DArrayOffset", "{g}sampler2DArray s, vec3 coord, ivec2 offset",
     "texture(s, vec3(coord.xy + {off2L}, coord.z){bias})", Expand::Sampler, kBias},
    {"{R}", "texture2DArrayLodOffset", "{g}sampler2DArray s, vec3 coord, float lod, ivec2 offset",
     "textureLod(s, vec3(coord.xy + {off2L}, coord.z), lod)", Expand::Sampler},
    {"vec4", "shadow1DArrayOffset", "sampler1DArrayShadow s, vec3 coord, int offset",
     "texture(s, vec3(coord.x + {off1L}, coord.yz){bias})", Expand::AsWritten, kShadow | kBias},
    {"vec4", "shadow1DArrayLodOffset", "sampler1DArrayShadow s, vec3 coord, float lod, int offset",
     "textureLod(s, vec3(coord.x + {off1L}, coord.yz), lod)", Expand::AsWritten, kShadow},
    {"vec4", "shadow2DArrayOffset", "sampler2DArrayShadow s, vec4 coord, ivec2 offset",
     "texture(s, vec4(coord.xy + {off2L}, coord.zw))", Expand::AsWritten, kShadow},
    {"{R}", "texture1DGradOffset", "{g}sampler1D s, float coord, float ddx, float ddy, int offset",
     "textureGrad(s, coord + {off1}, ddx, ddy)", Expand::Sampler},
    {"{R}", "texture1DProjGradOffset",
     "{g}sampler1D s, vec2 coord, float ddx, float ddy, int offset",
     "textureGrad(s, coord.x / coord.y + {off1}, ddx, ddy)", Expand::Sampler},
    {"{R}", "texture1DProjGradOffset",
     "{g}sampler1D s, vec4 coord, float ddx, float ddy, int offset",
     "textureGrad(s, coord.x / coord.w + {off1}, ddx, ddy)", Expand::Sampler},
    {"{R}", "texture1DArrayGradOffset",
     "{g}sampler1DArray s, vec2 coord, float ddx, float ddy, int offset",
     "textureGrad(s, vec2(coord.x + {off1L}, coord.y), ddx, ddy)", Expand::Sampler},
    {"{R}", "texture2DGradOffset", "{g}sampler2D s, vec2 coord, vec2 ddx, vec2 ddy, ivec2 offset",
     "textureGrad(s, coord + {off2}, ddx, ddy)", Expand::Sampler},
    {"{R}", "texture2DProjGradOffset",
     "{g}sampler2D s, vec3 coord, vec2 ddx, vec2 ddy, ivec2 offset",
     "textureGrad(s, coord.xy / coord.z + {off2}, ddx, ddy)", Expand::Sampler},
    {"{R}", "texture2DProjGradOffset",
     "{g}sampler2D s, vec4 coord, vec2 ddx, vec2 ddy, ivec2 offset",
     "textureGrad(s, coord.xy / coord.w + {off2}, ddx, ddy)", Expand::Sampler},
    {"{R}", "texture2DArrayGradOffset",
     "{g}sampler2DArray s, vec3 coord, vec2 ddx, vec2 ddy, ivec2 offset",
     "textureGrad(s, vec3(coord.xy + {off2L}, coord.z), ddx, ddy)", Expand::Sampler},
    {"{R}", "texture3DGradOffset", "{g}sampler3D s, vec3 coord, vec3 ddx, vec3 ddy, ivec3 offset",
     "textureGrad(s, coord + {off3}, ddx, ddy)", Expand::Sampler},
    {"{R}", "texture3DProjGradOffset",
     "{g}sampler3D s, vec4 coord, vec3 ddx, vec3 ddy, ivec3 offset",
     "textureGrad(s, coord.xyz / coord.w + {off3}, ddx, ddy)", Expand::Sampler},
    {"vec4", "shadow1DGradOffset",
     "sampler1DShadow s, vec3 coord, float ddx, float ddy, int offset",
     "textureGrad(s, vec3(coord.x + {off1}, coord.yz), ddx, ddy)", Expand::AsWritten, kShadow},
    {"vec4", "shadow1DProjGradOffset",
     "sampler1DShadow s, vec4 coord, float ddx, float ddy, int offset",
     "textureGrad(s, vec3(coord.x / coord.w + {off1}, coord.yz / coord.w), ddx, ddy)",
     Expand::AsWritten, kShadow},
    {"vec4", "shadow1DArrayGradOffset",
     "sampler1DArrayShadow s, vec3 coord, float ddx, float ddy, int offset",
     "textureGrad(s, vec3(coord.x + {off1L}, coord.yz), ddx, ddy)", Expand::AsWritten, kShadow},
    {"vec4", "shadow2DGradOffset",
     "sampler2DShadow s, vec3 coord, vec2 ddx, vec2 ddy, ivec2 offset",
     "textureGrad(s, vec3(coord.xy + {off2}, coord.z), ddx, ddy)", Expand::AsWritten, kShadow},
    {"vec4", "shadow2DProjGradOffset",
     "sampler2DShadow s, vec4 coord, vec2 ddx, vec2 ddy, ivec2 offset",
     "textureGrad(s, vec3(coord.xy / coord.w + {off2}, coord.z / coord.w), ddx, ddy)",
     Expand::AsWritten, kShadow},
    {"vec4", "shadow2DArrayGradOffset",
     "sampler2DArrayShadow s, vec4 coord, vec2 ddx, vec2 ddy, ivec2 offset",
     "textureGrad(s, vec4(coord.xy + {off2L}, coord.zw), ddx, ddy)", Expand::AsWritten, kShadow},
    {"vec4", "texture2DRectGradOffset",
     "sampler2DRect s, vec2 coord, vec2 ddx, vec2 ddy, ivec2 offset",
     "textureGrad(s, coord + vec2(offset), ddx, ddy)", Expand::AsWritten, kRect},
    {"vec4", "texture2DRectProjGradOffset",
     "sampler2DRect s, vec3 coord, vec2 ddx, vec2 ddy, ivec2 offset",
     "textureGrad(s, coord.xy / coord.z + vec2(offset), ddx, ddy)", Expand::AsWritten, kRect},
    {"vec4", "texture2DRectProjGradOffset",
     "sampler2DRect s, vec4 coord, vec2 ddx, vec2 ddy, ivec2 offset",
     "textureGrad(s, coord.xy / coord.w + vec2(offset), ddx, ddy)", Expand::AsWritten, kRect},
    {"vec4", "shadow2DRectGradOffset",
     "sampler2DRectShadow s, vec3 coord, vec2 ddx, vec2 ddy, ivec2 offset",
     "textureGrad(s, vec3(coord.xy + vec2(offset), coord.z), ddx, ddy)", Expand::AsWritten,
     kRect | kShadow},
    {"vec4", "shadow2DRectProjGradOffset",
     "sampler2DRectShadow s, vec4 coord, vec2 ddx, vec2 ddy, ivec2 offset",
     "textureGrad(s, vec3(coord.xy / coord.w + vec2(offset), coord.z / coord.w), ddx, ddy)",
     Expand::AsWritten, kRect | kShadow},

    // 8.3. round, and the integer abs, sign, min, max, clamp and uvec relational functions, are
    // 1.30 built-ins with the extension's signatures.
    {"{T}", "truncate", "{T} x", "trunc(x)", Expand::GenType},
};

// {offN}: the integer offset of an N-dimensional texture in normalised coordinates, at the base
// level; {offNL}: the same for a layered texture, whose last coordinate is the layer.
constexpr std::string_view kOffsetTokens[][2] = {
    {"off1", "float(offset) / float(textureSize(s, 0))"},
    {"off2", "vec2(offset) / vec2(textureSize(s, 0))"},
    {"off3", "vec3(offset) / vec3(textureSize(s, 0))"},
    {"off1L", "float(offset) / float(textureSize(s, 0).x)"},
    {"off2L", "vec2(offset) / vec2(textureSize(s, 0).xy)"},
};

// One overload's values for the tokens of a row.
struct Tokens {
  std::string_view prefix;    // {g}
  std::string_view result;    // {R}
  std::string_view gen_type;  // {T}
  std::string_view bias;      // {bias}: ", bias" or nothing
};

std::string Substitute(std::string_view text, const Tokens& tokens) {
  std::string out;
  for (size_t i = 0; i < text.size();) {
    if (text[i] != '{') {
      out += text[i++];
      continue;
    }
    const size_t close = text.find('}', i);
    const std::string_view token = text.substr(i + 1, close - i - 1);
    i = close + 1;
    if (token == "g") {
      out += tokens.prefix;
    } else if (token == "R") {
      out += tokens.result;
    } else if (token == "T") {
      out += tokens.gen_type;
    } else if (token == "bias") {
      out += tokens.bias;
    } else {
      for (const auto& [name, value] : kOffsetTokens) {
        if (token == name) out += value;
      }
    }
  }
  return out;
}

struct Options {
  bool vertex;
  bool gpu_shader4;
  bool rectangle;
};

void Emit(const Row& row, const Options& options, std::string* out) {
  if ((row.flags & kRect) && !options.rectangle) return;
  if ((row.flags & kVertexLod) && !options.gpu_shader4 && !options.vertex) return;

  constexpr Tokens kFloat{"", "vec4", "", ""};
  constexpr Tokens kInt{"i", "ivec4", "", ""};
  constexpr Tokens kUint{"u", "uvec4", "", ""};
  std::array<Tokens, 4> overloads;
  size_t count = 0;
  switch (row.expand) {
    case Expand::AsWritten:
      overloads[count++] = kFloat;
      break;
    case Expand::Sampler:
      overloads[count++] = kFloat;
      if (!options.gpu_shader4) break;  // integer samplers are gpu_shader4's
      [[fallthrough]];
    case Expand::IntSampler:
      overloads[count++] = kInt;
      overloads[count++] = kUint;
      break;
    case Expand::GenType:
      for (std::string_view type : {"float", "vec2", "vec3", "vec4"}) {
        overloads[count++] = Tokens{"", "", type, ""};
      }
      break;
  }

  // 1.10, 8.7: "The bias parameter is not accepted in a vertex shader."
  const bool bias = (row.flags & kBias) && !options.vertex;
  for (size_t i = 0; i < count; ++i) {
    for (int with_bias = 0; with_bias <= (bias ? 1 : 0); ++with_bias) {
      Tokens tokens = overloads[i];
      tokens.bias = with_bias ? ", bias" : "";
      *out += Substitute(row.ret, tokens);
      *out += ' ';
      *out += row.name;
      *out += '(';
      *out += Substitute(row.params, tokens);
      if (with_bias) *out += ", float bias";
      *out += ") { ";
      const std::string value = Substitute(row.body, tokens);
      if (row.flags & kShadow) {
        *out += "float r = " + value + "; return vec4(r, r, r, 1.0);";
      } else {
        *out += "return " + value + ";";
      }
      *out += " }\n";
    }
  }
}

std::string Build(bool vertex_stage, bool gpu_shader4, bool texture_array, bool texture_rectangle) {
  std::string out;
  const Options options{vertex_stage, gpu_shader4, texture_rectangle};
  if (gpu_shader4 || texture_array) {
    for (const Row& row : kTextureArray) Emit(row, options, &out);
  }
  if (gpu_shader4) {
    for (const Row& row : kGpuShader4) Emit(row, options, &out);
  }
  return out;
}

template <bool Vertex, bool GpuShader4, bool TextureArray, bool Rectangle>
std::string_view Cached() {
  static const std::string text = Build(Vertex, GpuShader4, TextureArray, Rectangle);
  return text;
}

}  // namespace

std::string_view Gpu4Preamble(bool vertex_stage, bool gpu_shader4, bool texture_array,
                              bool texture_rectangle) {
  using Getter = std::string_view (*)();
  // Indexed by the four flags as bits, vertex_stage the highest.
  static constexpr Getter kGetters[] = {
      Cached<false, false, false, false>, Cached<false, false, false, true>,
      Cached<false, false, true, false>,  Cached<false, false, true, true>,
      Cached<false, true, false, false>,  Cached<false, true, false, true>,
      Cached<false, true, true, false>,   Cached<false, true, true, true>,
      Cached<true, false, false, false>,  Cached<true, false, false, true>,
      Cached<true, false, true, false>,   Cached<true, false, true, true>,
      Cached<true, true, false, false>,   Cached<true, true, false, true>,
      Cached<true, true, true, false>,    Cached<true, true, true, true>,
  };
  const size_t index = (vertex_stage ? 8 : 0) | (gpu_shader4 ? 4 : 0) | (texture_array ? 2 : 0) |
                       (texture_rectangle ? 1 : 0);
  return kGetters[index]();
}

}  // namespace arbiter::glsl
