// Checking GLSL 1.10 vertex and fragment shaders: glslang compile and link, plus arbiter's
// own 1.10 rules where glslang and the specification disagree.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/limits.h"
#include "arbiter/compiler/source.h"

namespace arbiter::glsl {

enum class Stage { Vertex, Fragment };

// The stage a file name implies: .vert .vs -> vertex, .frag .fs -> fragment.
std::optional<Stage> StageFromPath(std::string_view path);

struct CheckOptions {
  // Also run glslang's link step on the single shader, so that link-time errors of one
  // shader (missing main, recursion, gl_FragColor with gl_FragData, a vertex shader that
  // never writes gl_Position) are reported. `arbiter check` always links.
  bool link = true;
  // Judge the shader as a program link would (piglit's `check_link: true`, `arbiter link`):
  // a vertex shader that never writes gl_Position is then an error, as drivers refuse to
  // link it; otherwise it is the warning the specification allows (GLSL 1.10 section 7.1:
  // "compilers may generate a diagnostic message").
  bool link_as_program = false;
};

struct CheckResult {
  bool ok = false;  // no errors
};

// Compiles (and links) the sources as one shader of `stage`: several files are
// concatenated in order, each keeping its own name and line numbers in diagnostics.
// Thread-safe: glslang is initialised once per process, one shader per call.
CheckResult CheckShader(Stage stage, const std::vector<const compiler::SourceFile*>& sources,
                        const CheckOptions& options, compiler::DiagnosticSink* sink);

// Every GLSL diagnostic kind (for docs and SARIF rules).
const std::vector<const compiler::DiagnosticInfo*>& AllDiagnostics();

}  // namespace arbiter::glsl
