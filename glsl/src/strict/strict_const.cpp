// GLSL 1.10 4.3.2: "Initializers for const declarations must be formed from literal values,
// other const variables (not including function call parameters), or expressions of these.
// Constructors may be used in such expressions, but function calls may not." glslang folds
// built-in calls such as sin(1.0) into constants (as GLSL 1.20 allows), so the call is gone
// from the AST: this rule reads the declaration's tokens instead. GLSL 1.10 only.
#include <fmt/format.h>

#include <cctype>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "strict.h"

namespace arbiter::glsl {
namespace {

const std::set<std::string_view>& ConstructorTypes() {
  static const std::set<std::string_view> types = {"float", "int",   "bool",  "vec2",  "vec3",
                                                   "vec4",  "ivec2", "ivec3", "ivec4", "bvec2",
                                                   "bvec3", "bvec4", "mat2",  "mat3",  "mat4"};
  return types;
}

}  // namespace

void CheckConstInitializers(const StrictContext& ctx) {
  if (ctx.version != 110) return;  // 1.20 4.3.3 allows built-in calls; glslang checks the rest
  for (const compiler::SourceFile* file : ctx.sources) {
    const std::vector<Token>& toks = SourceTokens(ctx, file);
    std::set<std::string_view> structs;
    for (size_t i = 0; i + 1 < toks.size(); ++i) {
      if (toks[i].text == "struct") structs.insert(toks[i + 1].text);
    }
    for (size_t i = 0; i < toks.size(); ++i) {
      if (toks[i].text != "const") continue;
      // Parameters ("const in float x") have no initializer; stop at ')' or ','.
      int depth = 0;
      bool initializer = false;
      for (size_t j = i + 1; j < toks.size(); ++j) {
        std::string_view t = toks[j].text;
        if (t == "(" || t == "[" || t == "{") ++depth;
        if (t == ")" || t == "]" || t == "}") {
          if (depth == 0) break;
          --depth;
        }
        if (depth == 0 && t == ";") break;
        if (depth == 0 && t == "=") initializer = true;
        if (depth == 0 && t == "," && !initializer) break;  // a parameter list
        if (depth == 0 && t == ",") initializer = false;    // next declarator
        bool call = initializer && IsIdentStart(t.front()) && j + 1 < toks.size() &&
                    toks[j + 1].text == "(" && !ConstructorTypes().count(t) && !structs.count(t);
        if (call) {
          ctx.sink->Report(
              Info(Diag::ConstInitializerCall), file,
              {toks[j].offset, static_cast<uint32_t>(toks[j].offset + t.size())},
              fmt::format("the initializer of a const variable calls '{}'; in GLSL 1.10 const "
                          "initializers may use constructors but no function calls",
                          t));
        }
      }
    }
  }
}

}  // namespace arbiter::glsl
