// The built-in functions of EXT_gpu_shader4 and EXT_texture_array as GLSL 1.30 source: glslang 12
// knows neither extension, so a shader that enables one is parsed as GLSL 1.30 with this text
// before it (extensions.def, Gpu4).
#pragma once

#include <string_view>

namespace arbiter::glsl {

// GLSL 1.30 definitions of the built-in functions EXT_gpu_shader4 and EXT_texture_array add to
// GLSL 1.10/1.20, under their names, for glslang (which knows neither extension).
//
// Only what 1.30 lacks is defined: the 1.10 lookups on float samplers (texture2D, shadow2DLod,
// ...), round and the integer common and relational functions are 1.30 built-ins already.
// Bias overloads exist only in the fragment stage (1.10, 8.7); with texture_array alone the
// Lod functions exist only in the vertex stage (1.10, 8.7), a restriction gpu_shader4 removes.
// gpu_shader4 includes the array functions and their integer-sampler overloads.
//
// The 'Rect' functions (gpu_shader4 only) need `texture_rectangle`: the extension has them only
// where ARB_texture_rectangle is supported, and glslang needs `#extension
// GL_ARB_texture_rectangle : enable` before this text to parse sampler2DRect.
//
// Known gaps, all from glslang's 1.30: no isampler2DRect, usampler2DRect, isamplerBuffer or
// usamplerBuffer types (so no overloads on them); no lookup on samplerBuffer (texelFetchBuffer
// and textureSizeBuffer are type-only stubs); an offset passed through a function is not a
// constant expression, so the *Offset functions accept any offset and apply it themselves.
//
// The text is built once per combination and lives for the program; empty when neither
// extension is enabled.
std::string_view Gpu4Preamble(bool vertex_stage, bool gpu_shader4, bool texture_array,
                              bool texture_rectangle = true);

}  // namespace arbiter::glsl
