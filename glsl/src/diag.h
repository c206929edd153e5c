// The glsl diagnostics table (diagnostics.def) as an enum and its static infos.
#pragma once

#include "arbiter/compiler/diagnostic.h"

namespace arbiter::glsl {

enum class Diag {
#define GLSL_DIAG(name, code, severity, summary, spec) name,
#include "diagnostics.def"
#undef GLSL_DIAG
};

const compiler::DiagnosticInfo& Info(Diag diag);

}  // namespace arbiter::glsl
