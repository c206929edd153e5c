// --driver-check: Mesa's verdict on a GLSL shader beside arbiter's, as a note when they differ.
#pragma once

#include <CLI/CLI.hpp>
#include <vector>

#include "arbiter/compiler/render.h"
#include "arbiter/compiler/source.h"
#include "arbiter/glsl/check.h"
#include "cli.h"

namespace arbiter::cli {

// Registers --driver-check and --driver (softpipe|llvmpipe) on `app` (arbiter check).
void AddDriverCheckOptions(CLI::App* app, CommonOptions* options);

// Compiles the shader made of `sources` with Mesa (and links it, as `arbiter check` does)
// through one OSMesa context, created at the first call and shared by all threads. When
// Mesa's verdict differs from arbiter's (whether `report` holds errors), appends a
// `driver-check-differs` note to `report` with both verdicts and Mesa's first error line.
// Returns Exit::Environment when Mesa cannot be started (said once on stderr) or a GL call
// failed (a `runtime-gl-error` error in `report`); otherwise Exit::Ok: the note never
// changes arbiter's verdict.
Exit DriverCheck(const CommonOptions& options, glsl::Stage stage,
                 const std::vector<const compiler::SourceFile*>& sources,
                 compiler::FileReport* report);

}  // namespace arbiter::cli
