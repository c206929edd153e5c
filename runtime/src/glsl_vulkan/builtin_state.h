// The values of GLSL 1.10's built-in uniform state (section 7.5) as Mesa feeds them, from the
// GL state through glstate: what the Vulkan engine puts in the uniforms the lowering declares
// for them (glsl/lower_vulkan.h).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "arbiter/arbvp/exec.h"

namespace arbiter::runtime::glsl_vulkan {

// The value of one element of built-in state, named by its GLSL path with constant indices:
// "gl_ModelViewMatrix", "gl_TextureMatrixInverse[2]", "gl_LightSource[1].spotCutoff",
// "gl_Fog.scale" (matrices column by column). False with `error` for a path the table lacks.
[[nodiscard]] bool BuiltinStateValue(std::string_view path, const arbvp::GlState& state,
                                     std::vector<float>* value, std::string* error);

}  // namespace arbiter::runtime::glsl_vulkan
