// glslang's info log -> arbiter diagnostics (file, line, column from the quoted token).
#pragma once

#include <vector>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/source.h"

namespace arbiter::glsl {

// Reports every ERROR/WARNING of a glslang info log. Compile messages carry
// "name:line:"; link messages carry no location and are placed at the construct they name.
void ReportInfoLog(const char* log, const std::vector<const compiler::SourceFile*>& sources,
                   bool link, compiler::DiagnosticSink* sink);

}  // namespace arbiter::glsl
