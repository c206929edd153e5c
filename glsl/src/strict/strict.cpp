// Runs the strictness checks in chapter order.
#include "strict.h"

#include <cctype>

namespace arbiter::glsl {

bool FindDeclaration(const StrictContext& ctx, std::string_view name, std::string_view keyword,
                     const compiler::SourceFile** file, compiler::Range* range) {
  auto is_ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (const compiler::SourceFile* f : ctx.sources) {
    for (uint32_t n = 1; n <= f->line_count(); ++n) {
      std::string_view line = f->LineText(n);
      if (!keyword.empty() && line.find(keyword) == std::string_view::npos) continue;
      for (size_t at = line.find(name); at != std::string_view::npos;
           at = line.find(name, at + 1)) {
        bool before = at == 0 || !is_ident(line[at - 1]);
        bool after = at + name.size() >= line.size() || !is_ident(line[at + name.size()]);
        if (before && after) {
          *file = f;
          uint32_t begin = f->LineStart(n) + static_cast<uint32_t>(at);
          *range = {begin, static_cast<uint32_t>(begin + name.size())};
          return true;
        }
      }
    }
  }
  return false;
}

void RunStrictChecks(const StrictContext& ctx) {
  CheckPreprocessor(ctx);
  CheckQualifiers(ctx);
  CheckConstInitializers(ctx);
  CheckBuiltinVariables(ctx);
}

}  // namespace arbiter::glsl
