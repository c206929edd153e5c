// The GLSL extensions arbiter knows (extensions.def) and the set a target has.
#pragma once

#include <string_view>
#include <vector>

#include "arbiter/compiler/limits.h"

namespace arbiter::glsl {

enum class ExtensionSupport { Native, Core, Include, Gpu4 };

struct Extension {
  std::string_view name;
  ExtensionSupport support;
  bool mesa;
  // Added to a vertex shader's preamble when the shader enables it (extensions.def).
  std::string_view vertex_preamble;
  std::string_view spec;
};

// Every known extension, in the table's order.
const std::vector<Extension>& KnownExtensions();
// The extension of that name; nullptr when arbiter does not know it.
const Extension* FindExtension(std::string_view name);

// Whether the target of `profile` has the extension: the profile's own list when it names
// one, else Mesa's for the default (nullptr) and "mesa" profiles (and JSON profiles based on
// "mesa"), none for "spec-min".
bool ProfileHas(const compiler::LimitProfile* profile, const Extension& extension);

// "GL_ARB_texture_rectangle, GL_ARB_draw_buffers, ...": the names `profile` has.
std::string ProfileExtensionList(const compiler::LimitProfile* profile);

}  // namespace arbiter::glsl
