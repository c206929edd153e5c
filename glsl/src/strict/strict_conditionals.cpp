// GLSL 1.10 3.3: "Expressions following #if and #elif are restricted to expressions operating
// on literal integer constants, plus identifiers consumed by the defined operator." glslang
// (as a C preprocessor) takes any other identifier left after macro expansion as 0, silently.
// This rule follows the conditional directives as a preprocessor does (conditionals.h),
// expanding object-like macros, and reports such an identifier in every #if or #elif that is
// evaluated. Where it cannot tell a value (a function-like macro), it reports nothing inside
// that group.
#include <fmt/format.h>

#include <algorithm>
#include <string>

#include "../conditionals.h"
#include "strict.h"

namespace arbiter::glsl {

void CheckConditionals(const StrictContext& ctx) {
  GroupTracker tracker(ctx.preamble);
  for (size_t index = 0; index < ctx.sources.size(); ++index) {
    for (const Directive& d : Directives(BlankedText(ctx, index))) {
      for (const Token& t : tracker.Follow(d).undefined) {
        ctx.sink->Report(
            Info(Diag::IfUndefinedIdentifier), ctx.sources[index],
            {t.offset, static_cast<uint32_t>(t.offset + std::min(t.text.size(), size_t{64}))},
            fmt::format("'{}' is not a macro: #if and #elif expressions operate on "
                        "integer literals and 'defined' only (GLSL 1.10 section "
                        "3.3); glslang takes an undefined name as 0",
                        t.text));
      }
    }
  }
}

}  // namespace arbiter::glsl
