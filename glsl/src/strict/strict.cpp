// Runs the strictness checks in chapter order.
#include "strict.h"

#include <glslang/MachineIndependent/localintermediate.h>

#include <cctype>

namespace arbiter::glsl {

bool FindDeclaration(const StrictContext& ctx, std::string_view name, std::string_view keyword,
                     const compiler::SourceFile** file, compiler::Range* range) {
  for (const compiler::SourceFile* f : ctx.sources) {
    for (uint32_t n = 1; n <= f->line_count(); ++n) {
      std::string_view line = f->LineText(n);
      if (!keyword.empty() && line.find(keyword) == std::string_view::npos) continue;
      for (size_t at = line.find(name); at != std::string_view::npos;
           at = line.find(name, at + 1)) {
        bool before = at == 0 || !IsIdentChar(line[at - 1]);
        bool after = at + name.size() >= line.size() || !IsIdentChar(line[at + name.size()]);
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

const std::vector<Token>& SourceTokens(const StrictContext& ctx, size_t index) {
  if (ctx.tokens.empty()) {
    ctx.tokens.reserve(ctx.sources.size());
    for (const compiler::SourceFile* file : ctx.sources)
      ctx.tokens.push_back(Tokenize(file->text()));
  }
  return ctx.tokens[index];
}

const std::vector<Token>& SourceTokens(const StrictContext& ctx, const compiler::SourceFile* file) {
  size_t index = 0;
  while (index + 1 < ctx.sources.size() && ctx.sources[index] != file) ++index;
  return SourceTokens(ctx, index);
}

const std::string& BlankedText(const StrictContext& ctx, size_t index) {
  if (ctx.blanked.empty()) {
    ctx.blanked.reserve(ctx.sources.size());
    for (const compiler::SourceFile* file : ctx.sources) {
      ctx.blanked.push_back(BlankComments(file->text()));
    }
  }
  return ctx.blanked[index];
}

bool RangeOfLoc(const StrictContext& ctx, const glslang::TSourceLoc& loc, size_t length,
                const compiler::SourceFile** file, compiler::Range* range) {
  if (loc.string < 0 || static_cast<size_t>(loc.string) >= ctx.sources.size() || loc.line < 1) {
    return false;
  }
  *file = ctx.sources[static_cast<size_t>(loc.string)];
  if (static_cast<uint32_t>(loc.line) > (*file)->line_count()) return false;
  uint32_t begin = (*file)->LineStart(static_cast<uint32_t>(loc.line)) +
                   static_cast<uint32_t>(loc.column > 0 ? loc.column - 1 : 0);
  if (begin + length > (*file)->text().size()) return false;
  *range = {begin, static_cast<uint32_t>(begin + length)};
  return true;
}

std::string_view VersionName(const StrictContext& ctx) {
  return ctx.version == 120 ? "GLSL 1.20" : "GLSL 1.10";
}

void RunStrictChecks(const StrictContext& ctx) {
  CheckPreprocessor(ctx);
  CheckConditionals(ctx);
  CheckQualifiers(ctx);
  CheckConstInitializers(ctx);
  CheckFloatLiterals(ctx);
  CheckArraySizes(ctx);
  CheckExpressions(ctx);
  CheckUnaryPlus(ctx);
  CheckFunctions(ctx);
  CheckBuiltinVariables(ctx);
}

void RunLinkStrictChecks(const StrictContext& ctx) {
  CheckFragmentOutputs(ctx);
  CheckPositionWritten(ctx);
}

}  // namespace arbiter::glsl
