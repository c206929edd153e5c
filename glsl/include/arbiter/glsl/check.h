// Checking GLSL 1.10 and 1.20 vertex and fragment shaders: glslang compile (and link), plus
// arbiter's own rules of each version where glslang and the specification disagree.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/limits.h"
#include "arbiter/compiler/source.h"

namespace arbiter::glsl {

enum class Stage { Vertex, Fragment };

// The stage a file name implies: .vert .vs .vsh .vert.glsl -> vertex, .frag .fs .fsh
// .frag.glsl -> fragment. A bare .glsl names no stage (nullopt, as for any other name).
std::optional<Stage> StageFromPath(std::string_view path);
// Whether the name is a GLSL file's (a stage's extension, or .glsl).
bool IsGlslPath(std::string_view path);

// What the preprocessor is given besides the shader's own text (the options a pipeline
// passes): each applies after #version, before the first line of the shader.
struct PreprocessorOptions {
  // -D NAME[=VALUE] and -U NAME, in command-line order: "NAME", "NAME=VALUE" or "-NAME".
  std::vector<std::string> defines;
  // --preamble FILE: text the application puts before the shader (after #version).
  const compiler::SourceFile* preamble = nullptr;
  // -I DIR: where #include "name" and <name> are looked up, after the including file's
  // directory (GL_ARB_shading_language_include).
  std::vector<std::string> include_dirs;
};

struct CheckOptions {
  // false: the shader is judged as glCompileShader judges it (a shader object: prototypes
  // without a body and a missing main() are allowed). true: as a program of this one shader
  // (piglit's `check_link: true`): glslang's link step runs, so main(), every called function's
  // body and a vertex shader's gl_Position write are required.
  bool link = false;
  // The implementation limits and extensions of the target (--limits); nullptr: Mesa's.
  const compiler::LimitProfile* profile = nullptr;
  PreprocessorOptions preprocessor;
};

struct CheckResult {
  bool ok = false;  // no errors
  // The files #include read: diagnostics may point into them, so they must outlive those.
  std::vector<std::unique_ptr<compiler::SourceFile>> included;
};

// Compiles (and with `link`, links) the sources as one shader of `stage`: several files are
// concatenated in order, each keeping its own name and line numbers in diagnostics.
// `#version 110` (or none) is GLSL 1.10, `#version 120` GLSL 1.20, each with its own rules.
// Thread-safe: glslang is initialised once per process, one shader per call.
CheckResult CheckShader(Stage stage, const std::vector<const compiler::SourceFile*>& sources,
                        const CheckOptions& options, compiler::DiagnosticSink* sink);

// Every GLSL diagnostic kind (for docs and SARIF rules).
const std::vector<const compiler::DiagnosticInfo*>& AllDiagnostics();

}  // namespace arbiter::glsl
