// api-check: checks one ARB program with arbiter's libraries, translates it to GLSL 1.10 and
// runs it on the reference interpreter: what a pipeline tool does without spawning `arbiter`.
//   api-check PROGRAM.vp|PROGRAM.fp [OUT.glsl]
// Exit status as the arbiter command's: 0 ok, 1 rejected, 2 usage, 3 I/O or internal error.
#include <cstdio>
#include <string>

#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/interpret.h"
#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/render.h"
#include "arbiter/compiler/source.h"
#include "arbiter/runtime/translate.h"

namespace compiler = arbiter::compiler;
namespace arbvp = arbiter::arbvp;

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: api-check PROGRAM [OUT.glsl]\n");
    return 2;
  }
  const std::string path = argv[1];

  // 1. Read and check. Libraries never print: diagnostics are data in a sink.
  std::string bytes, error;
  if (!compiler::ReadFileBytes(path, &bytes, &error)) {
    std::fprintf(stderr, "api-check: cannot read '%s': %s\n", path.c_str(), error.c_str());
    return 3;
  }
  compiler::SourceFile source(path, std::move(bytes));
  compiler::DiagnosticSink sink;
  arbvp::CheckOptions check_options;
  check_options.profile = compiler::BuiltinProfile("mesa");  // or "r300", "i915", ...
  arbvp::CheckResult checked = arbvp::CheckProgram(source, check_options, &sink);
  sink.PromoteWarnings();  // -Werror
  compiler::FileReport report{path, sink.diagnostics(), sink.dropped()};
  std::fputs(compiler::RenderText(report, compiler::TextOptions{}).c_str(), stderr);
  if (!checked.ok || sink.error_count() > 0) return 1;
  std::printf("%s: ok, %d instructions (%d ALU, %d TEX)\n", path.c_str(),
              checked.stats.instructions, checked.stats.alu_instructions,
              checked.stats.tex_instructions);

  // 2. Translate; the translation is compiled by glslang before it is returned.
  const bool vertex = checked.program->kind == arbvp::ProgramKind::Vertex;
  arbiter::runtime::CheckedTranslation glsl = arbiter::runtime::TranslateChecked(
      vertex ? checked.program.get() : nullptr, vertex ? nullptr : checked.program.get(),
      arbvp::EmitOptions{}, vertex ? &source : nullptr, vertex ? nullptr : &source);
  if (!glsl.ok) {
    std::fprintf(stderr, "api-check: internal error: %s\n", glsl.error.c_str());
    return 3;
  }
  const std::string& text = vertex ? glsl.vertex : glsl.fragment;
  if (argc == 3 && !compiler::WriteFileAtomically(argv[2], text, &error)) {
    std::fprintf(stderr, "api-check: cannot write '%s': %s\n", argv[2], error.c_str());
    return 3;
  }
  std::printf("translated: %zu bytes of GLSL, %zu uniform arrays, %zu samplers\n", text.size(),
              glsl.bindings.parameters.size(), glsl.bindings.samplers.size());

  // 3. Run it on one input vector: GL's initial state, program.local[0] = (1, 2, 3, 4).
  arbvp::ExecInputs inputs;
  (vertex ? inputs.vertex_params : inputs.fragment_params).local[0] = {1.0f, 2.0f, 3.0f, 4.0f};
  inputs.vectors.emplace_back();
  for (const arbvp::VectorResult& result : arbvp::Interpret(*checked.program, inputs, &source)) {
    if (result.killed) std::printf("killed\n");
    for (const arbvp::OutputRegister& out : result.outputs) {
      std::printf("%s = (%g, %g, %g, %g)\n", out.name.c_str(), static_cast<double>(out.value[0]),
                  static_cast<double>(out.value[1]), static_cast<double>(out.value[2]),
                  static_cast<double>(out.value[3]));
    }
  }
  return 0;
}
