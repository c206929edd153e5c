// Shared helpers of the emitter tests: check an ARB program, translate it, check the GLSL.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/emit.h"

namespace arbiter::arbvp::testing {

// A checked program with the source it came from (the source must outlive translations).
struct Checked {
  std::unique_ptr<compiler::SourceFile> source;
  std::unique_ptr<Program> program;
  std::string errors;  // rendered diagnostics when the check failed
};

Checked CheckText(const std::string& name, const std::string& text);
// Translates ARB text (which must check) with the given options.
Translation TranslateText(const std::string& text, const EmitOptions& options = {});
// Runs glslang on GLSL text; returns "" when accepted, else the error messages.
std::string GlslErrors(ProgramKind stage, const std::string& glsl);
// The main() statement lines of a translation without comments, indentation or locals'
// declarations: the statements the instructions became.
std::vector<std::string> Statements(const std::string& glsl);

// Valid corpus programs, as paths relative to corpus/arb.
std::vector<std::string> ValidCorpusFiles();
std::string ReadFile(const std::string& path);

}  // namespace arbiter::arbvp::testing
