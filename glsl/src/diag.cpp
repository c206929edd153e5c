// Expansion of the glsl diagnostics table.
#include "diag.h"

#include "arbiter/glsl/check.h"

namespace arbiter::glsl {
namespace {

using compiler::DiagnosticInfo;
using compiler::Severity;

const DiagnosticInfo kInfos[] = {
#define GLSL_DIAG(name, code, severity, summary, spec) \
  DiagnosticInfo{code, Severity::severity, summary, spec},
#include "diagnostics.def"
#undef GLSL_DIAG
};

}  // namespace

const DiagnosticInfo& Info(Diag diag) { return kInfos[static_cast<size_t>(diag)]; }

const std::vector<const DiagnosticInfo*>& AllDiagnostics() {
  static const std::vector<const DiagnosticInfo*> all = [] {
    std::vector<const DiagnosticInfo*> list;
    for (const DiagnosticInfo& info : kInfos) list.push_back(&info);
    return list;
  }();
  return all;
}

}  // namespace arbiter::glsl
