// arbiter verify's GLSL inputs: shaders named .vert/.frag (or found under directories) and
// the GLSL shaders of piglit .shader_test files, checked by arbiter's GLSL checker and
// reflected, as runtime::VerifyGlsl subjects. docs/verify.md, "GLSL shaders".
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "arbiter/glsl/reflect.h"
#include "arbiter/runtime/glsl_verify.h"
#include "cli.h"

namespace arbiter::cli {

struct LoadedGlsl {
  std::vector<std::unique_ptr<compiler::SourceFile>> files;
  std::vector<std::unique_ptr<glsl::Reflection>> reflections;
  std::vector<runtime::GlslVerifySubject> subjects;
  std::vector<compiler::FileReport> reports;  // diagnostics of rejected shaders
  size_t rejected = 0;                        // shaders (or tests) with errors: not verified
  size_t skipped = 0;  // .shader_test files without GLSL (ARB only) or with several shaders
};

// Whether an argument is verify's as GLSL: a shader named by its stage or a .shader_test.
bool IsVerifyGlslPath(const std::string& path);

// Loads the GLSL subjects of `args` (files and directories; directories give every GLSL
// shader and .shader_test under them). With `pair`, the one vertex and one fragment shader
// named form one subject. Exit::Environment when a file cannot be read, Usage for a bad
// --pair.
Exit LoadGlslSubjects(const std::vector<std::string>& args, bool pair, LoadedGlsl* out);

}  // namespace arbiter::cli
