// What glslang is given for one shader: the directives arbiter reads before glslang (#version,
// #extension, #include), the text rewrites of source_text.h, and the preamble (-D, -U, the
// implicit extension enables, --preamble). Shared by CheckShader and the reflection, so that
// both parse the same text.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/source.h"
#include "arbiter/glsl/check.h"

namespace glslang {
class TShader;
}

namespace arbiter::glsl {

struct PreparedShader {
  // The language version whose rules apply: 110 or 120.
  int version = 110;
  // false: the shader's #version is one arbiter does not check (reported); nothing more to do.
  bool checked = true;
  // An extension of the Gpu4 kind is enabled: glslang parses the shader as GLSL 1.30 with the
  // extension's names mapped onto 1.30's (extensions.def).
  bool gpu4 = false;
  // The strings glslang parses, one per source, each with the user's lines and columns.
  std::vector<std::string> texts;
  // The files of the strings: the sources, then the files #include brought in (owned here).
  std::vector<const compiler::SourceFile*> files;
  std::vector<std::unique_ptr<compiler::SourceFile>> included;
  // glslang's preamble (placed after #version), and the file it comes from, if any.
  std::string preamble;
  // Lines of `preamble` before the text of --preamble's file.
  int preamble_generated_lines = 0;
};

// Reads the directives of `sources` (one shader's strings), reporting what is wrong with them
// into `sink` (which may be a scratch sink), and makes glslang's input.
PreparedShader PrepareShader(Stage stage, const std::vector<const compiler::SourceFile*>& sources,
                             const CheckOptions& options, compiler::DiagnosticSink* sink);

// A glslang shader of `stage` parsed from `prepared`; `parsed` says whether glslang accepted it.
// glslang must be initialised (EnsureGlslang).
std::unique_ptr<glslang::TShader> ParsePrepared(Stage stage, const PreparedShader& prepared,
                                                bool* parsed);

// glslang::InitializeProcess, once per process.
void EnsureGlslang();

}  // namespace arbiter::glsl
