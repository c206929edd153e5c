// glslang's info log -> arbiter diagnostics (file, line, column from the quoted token).
#pragma once

#include <vector>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/source.h"
#include "arbiter/glsl/check.h"

namespace arbiter::glsl {

// What a log is read against.
struct InfoLogContext {
  const std::vector<const compiler::SourceFile*>& sources;  // string N of the log is sources[N]
  Stage stage;
  int version = 110;    // the language version whose rules apply (110 or 120)
  bool program = true;  // judged as a program (CheckOptions::link), not a shader object
  // The shader's preamble (prepare.h), for messages in it; nullptr when none.
  const struct PreparedShader* prepared = nullptr;
};

// Reports every ERROR/WARNING of a glslang info log. Compile messages carry
// "<string>:<line>:"; link messages carry no location and are placed at the construct they
// name. Errors that the shader's version does not make, and link errors of what only a program
// needs when a shader object is checked, are dropped; returns how many.
int ReportInfoLog(const char* log, const InfoLogContext& ctx, bool link,
                  compiler::DiagnosticSink* sink);

// Whether a failed glslang step reported only such dropped errors, so that its result stands
// (as ReportInfoLog, into no sink).
bool OnlyRelaxedErrors(const char* log, const InfoLogContext& ctx, bool link);

}  // namespace arbiter::glsl
