#include "extensions.h"

#include <algorithm>
#include <string>

namespace arbiter::glsl {

const std::vector<Extension>& KnownExtensions() {
  static const std::vector<Extension> table = {
#define GLSL_EXTENSION(name, spelling, support, mesa, vertex_preamble, spec) \
  Extension{spelling, ExtensionSupport::support, mesa, vertex_preamble, spec},
#include "extensions.def"
#undef GLSL_EXTENSION
  };
  return table;
}

const Extension* FindExtension(std::string_view name) {
  for (const Extension& e : KnownExtensions()) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

bool ProfileHas(const compiler::LimitProfile* profile, const Extension& extension) {
  if (profile == nullptr) return extension.mesa;
  if (profile->glsl_extensions) {
    const std::vector<std::string>& list = *profile->glsl_extensions;
    return std::find(list.begin(), list.end(), extension.name) != list.end();
  }
  return profile->base == "mesa" && extension.mesa;
}

std::string ProfileExtensionList(const compiler::LimitProfile* profile) {
  std::string out;
  for (const Extension& e : KnownExtensions()) {
    if (!ProfileHas(profile, e)) continue;
    if (!out.empty()) out += ", ";
    out += e.name;
  }
  return out.empty() ? "none" : out;
}

}  // namespace arbiter::glsl
