// glslang's info log -> arbiter diagnostics (file, line, column from the quoted token).
#pragma once

#include <vector>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/source.h"
#include "arbiter/glsl/check.h"

namespace arbiter::glsl {

// Reports every ERROR/WARNING of a glslang info log. Compile messages carry
// "<string>:<line>:"; link messages carry no location and are placed at the construct they
// name. Errors that GLSL 1.10 does not make are dropped; returns how many.
int ReportInfoLog(const char* log, const std::vector<const compiler::SourceFile*>& sources,
                  Stage stage, bool link, compiler::DiagnosticSink* sink);

// Whether a failed glslang step reported only errors that GLSL 1.10 does not make, so that
// its result stands (as ReportInfoLog, into no sink).
bool OnlyRelaxedErrors(const char* log, const std::vector<const compiler::SourceFile*>& sources,
                       Stage stage, bool link);

// The same for messages of no particular stage (a two-stage program link).
inline void ReportInfoLog(const char* log, const std::vector<const compiler::SourceFile*>& sources,
                          bool link, compiler::DiagnosticSink* sink) {
  ReportInfoLog(log, sources, Stage::Fragment, link, sink);
}

}  // namespace arbiter::glsl
