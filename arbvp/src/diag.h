// The arbvp diagnostics table (diagnostics.def) as an enum and its static infos.
#pragma once

#include "arbiter/compiler/diagnostic.h"

namespace arbiter::arbvp {

enum class Diag {
#define ARBVP_DIAG(name, code, severity, summary, spec) name,
#include "diagnostics.def"
#undef ARBVP_DIAG
};

const compiler::DiagnosticInfo& Info(Diag diag);

}  // namespace arbiter::arbvp
