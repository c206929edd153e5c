// Limit profiles: named sets of implementation limits (data, not code).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace arbiter::compiler {

// One implementation limit. Keys are "<stage>.<name>", e.g. "arbvp.max_instructions",
// "arbfp.max_tex_indirections"; the full list is LimitKeys().
struct LimitKey {
  std::string_view key;
  std::string_view gl_name;  // the GL query it mirrors, e.g. "MAX_PROGRAM_INSTRUCTIONS_ARB"
  std::string_view description;
};

// Every known key, in a stable order.
const std::vector<LimitKey>& LimitKeys();

struct LimitProfile {
  std::string name;
  // The built-in profile it derives from (BuiltinProfileNames(); its own name for those).
  std::string base;
  std::map<std::string, int64_t, std::less<>> values;
  // The GLSL extensions the target has, when the profile lists them ("extensions" in JSON);
  // otherwise those of `base` (glsl/src/extensions.def).
  std::optional<std::vector<std::string>> glsl_extensions;

  // The value of a key (every built-in profile defines every key).
  int64_t Get(std::string_view key) const;
};

// Built-in profiles: "spec-min" (the minimum maximums the specifications require), "mesa"
// (what Mesa 22.3 reports through OSMesa), and the native limits of GPUs that ran ARB
// programs, as Mesa's drivers report them: "r300" (Radeon 9500-X850), "r500" (Radeon X1000),
// "i915" (Intel GMA 900/950), "nv30" (GeForce FX), "nv40" (GeForce 6/7); limits.def has the
// values and their sources. Returns nullptr for another name.
const LimitProfile* BuiltinProfile(std::string_view name);
std::vector<std::string_view> BuiltinProfileNames();

// Loads `--limits ARG`: a built-in profile name, or a JSON file
// {"name": "...", "base": "spec-min"|"mesa"|"r300"|...,
//  "limits": {"arbvp.max_instructions": 256, ...},
//  "extensions": ["GL_ARB_texture_rectangle", ...]}
// whose keys override the base (default base: spec-min); "extensions", when present, is the
// whole list of GLSL extensions the target has. Unknown keys, non-integer or
// negative values are errors: returns nullopt and sets `error`.
std::optional<LimitProfile> LoadLimitProfile(const std::string& arg, std::string* error);

}  // namespace arbiter::compiler
