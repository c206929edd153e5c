// The semantic check families, run in a fixed order by checker.cpp.
#pragma once

#include <set>
#include <string_view>

#include "../diag.h"
#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/ir.h"
#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/limits.h"

namespace arbiter::arbvp {

struct CheckContext {
  const Program& program;
  const compiler::SourceFile& source;
  compiler::DiagnosticSink* sink;
  // Explicit profile (--limits), or null for Mesa's limits (the mesa profile).
  const compiler::LimitProfile* profile;
  Stats* stats;
  int errors_before = 0;  // the sink's error count before this program
  bool vp() const { return program.kind == ProgramKind::Vertex; }
  compiler::Diagnostic* Report(Diag diag, Range range, std::string message) const {
    return sink->Report(Info(diag), &source, range, std::move(message));
  }
  // The limit key of a stage-specific resource: "arbvp.<name>" or "arbfp.<name>".
  std::string_view StageKey(std::string_view name) const;
  // The value of limit `key` in the enforced profile (--limits, else mesa).
  int64_t EnforcedLimit(std::string_view key) const;
};

// Checks `used` against the limit `key` (minus `reserve`, what options take for
// themselves). `used` is a count, or index + 1 for a selector. Reports `diag` (error) when
// over the enforced limit. Returns false when it did.
bool CheckLimit(const CheckContext& ctx, std::string_view key, int64_t used, int reserve, Diag diag,
                Range range, std::string_view what);

// The largest `used` that CheckLimit passes without a diagnostic; hot callers compare with
// it first so that they build the message only when one may be reported.
int64_t QuietLimit(const CheckContext& ctx, std::string_view key, int reserve);

// The variables some instruction indexes with an address register.
std::set<int> RelativelyAddressed(const Program& program);

void CheckProgramOptions(const CheckContext& ctx);  // check_options.cpp
void CheckBindings(const CheckContext& ctx);        // check_bindings.cpp
void CheckOperands(const CheckContext& ctx);        // check_operands.cpp
void CheckTextures(const CheckContext& ctx);        // check_textures.cpp
void CheckResources(const CheckContext& ctx);       // check_limits.cpp

}  // namespace arbiter::arbvp
