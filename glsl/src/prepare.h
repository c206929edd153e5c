// What glslang is given for one shader: the directives arbiter reads before glslang (#version,
// #extension, #include), the text rewrites of source_text.h, and the preamble (-D, -U, the
// implicit extension enables, --preamble). Shared by CheckShader and the reflection, so that
// both parse the same text.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/source.h"
#include "arbiter/glsl/check.h"
#include "source_text.h"

namespace glslang {
class TShader;
}

namespace arbiter::glsl {

struct PreparedShader {
  // The language version whose rules apply: 110 or 120.
  int version = 110;
  // false: the shader's #version is one arbiter does not check (reported); nothing more to do.
  bool checked = true;
  // GL_EXT_gpu_shader4 or GL_EXT_texture_array is enabled: glslang parses the shader as GLSL
  // 1.30, with the extensions' functions defined in the preamble (gpu4_preamble.h) and their
  // spellings of 1.30 words rewritten ("unsigned int", "varying out").
  bool gpu_shader4 = false;
  bool texture_array = false;
  bool gpu4() const { return gpu_shader4 || texture_array; }
  // Where the number of the shader's #version is in texts[0]; npos without one.
  size_t version_offset = std::string::npos;
  // The strings glslang parses, one per source, each with the user's lines and columns.
  std::vector<std::string> texts;
  // The files of the strings (the sources), and those #include brought in while parsing (owned
  // here; diagnostics in them name them).
  std::vector<const compiler::SourceFile*> files;
  std::vector<std::unique_ptr<compiler::SourceFile>> included;
  // GL_ARB_shading_language_include is enabled: #include is read (glslang's include
  // directive), from the including file's directory and then `include_dirs`.
  bool include = false;
  std::vector<std::string> include_dirs;
  // Why an #include failed other than by not finding its file, by the name it gave.
  std::map<std::string, std::string, std::less<>> include_failures;
  // The preamble text of the extensions the shader enables (Extension::vertex_preamble).
  std::string enabled_preamble;
  // glslang's preamble (placed after #version): arbiter's lines, then --preamble's file.
  std::string preamble;
  // Lines of `preamble` before the text of --preamble's file, and that file (or nullptr).
  uint32_t preamble_generated_lines = 0;
  const compiler::SourceFile* preamble_file = nullptr;
  // The functions renamed in `texts` and `preamble` for 1.10's separate name spaces
  // (function_names.h); messages and AST names are spelled back with them.
  std::vector<Rename> renames;
};

// Reads the directives of `sources` (one shader's strings), reporting what is wrong with them
// into `sink` (which may be a scratch sink), and makes glslang's input.
PreparedShader PrepareShader(Stage stage, const std::vector<const compiler::SourceFile*>& sources,
                             const CheckOptions& options, compiler::DiagnosticSink* sink);

// A glslang shader of `stage` parsed from `prepared`; `parsed` says whether glslang accepted it.
// The files #include read are added to prepared->included.
std::unique_ptr<glslang::TShader> ParsePrepared(Stage stage, PreparedShader* prepared,
                                                bool* parsed);

// The included file a glslang location names ("dir/common.glsl"), or nullptr.
const compiler::SourceFile* IncludedFile(const PreparedShader& prepared, std::string_view name);

// glslang::InitializeProcess, once per process.
void EnsureGlslang();

}  // namespace arbiter::glsl
