// CheckShader: glslang compile and link of one GLSL 1.10 shader, its info log turned into
// arbiter diagnostics, then arbiter's own 1.10 rules.
#include "arbiter/glsl/check.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <mutex>
#include <string>

#include "charset.h"
#include "diag.h"
#include "info_log.h"
#include "source_text.h"
#include "strict/strict.h"
#include "version_gate.h"

namespace arbiter::glsl {
namespace {

std::once_flag g_glslang_initialised;

void EnsureGlslang() {
  std::call_once(g_glslang_initialised, [] { glslang::InitializeProcess(); });
}

EShLanguage Language(Stage stage) {
  return stage == Stage::Vertex ? EShLangVertex : EShLangFragment;
}

// Every error, not only the first (platform.md: EShMsgCascadingErrors).
constexpr auto kMessages = static_cast<EShMessages>(EShMsgCascadingErrors);

}  // namespace

std::optional<Stage> StageFromPath(std::string_view path) {
  auto dot = path.rfind('.');
  if (dot == std::string_view::npos) return std::nullopt;
  std::string_view ext = path.substr(dot);
  if (ext == ".vert" || ext == ".vs") return Stage::Vertex;
  if (ext == ".frag" || ext == ".fs") return Stage::Fragment;
  return std::nullopt;
}

CheckResult CheckShader(Stage stage, const std::vector<const compiler::SourceFile*>& sources,
                        const CheckOptions& options, compiler::DiagnosticSink* sink) {
  EnsureGlslang();
  CheckResult result;
  int errors_before = sink->error_count() + sink->dropped();
  if (sources.empty()) return result;

  // The text glslang parses keeps every line and column of the user's (source_text.h).
  std::vector<std::string> texts;
  for (const compiler::SourceFile* file : sources) {
    std::string blanked = ReportInvalidCharacters(*file, sink);
    // #version belongs to the first string (3.3: before anything else).
    std::string gated;
    if (texts.empty() &&
        GateVersion(*file, blanked.empty() ? file->text() : blanked, &gated, sink)) {
      blanked = std::move(gated);
    }
    texts.push_back(PrepareForGlslang(blanked.empty() ? file->text() : blanked));
  }
  std::vector<const char*> strings;
  std::vector<int> lengths;
  for (const std::string& text : texts) {
    strings.push_back(text.data());
    lengths.push_back(static_cast<int>(text.size()));
  }
  glslang::TShader shader(Language(stage));
  // No names: glslang would then expand __FILE__ to a file name, where GLSL 1.10 (3.3) says
  // it is the source string number. Messages say "<string>:<line>:".
  shader.setStringsWithLengths(strings.data(), lengths.data(), static_cast<int>(strings.size()));
  // A shader without #version is 1.10 desktop (the default version matters: without it
  // glslang takes such a shader as ES 1.00).
  bool compiled = shader.parse(GetDefaultResources(), 110, ENoProfile, false, false, kMessages);
  int relaxed = ReportInfoLog(shader.getInfoLog(), sources, stage, /*link=*/false, sink);
  // Only errors that GLSL 1.10 does not make (see info_log.cpp): glslang recovered from each
  // of them, so its AST is the shader's and the link step and the strictness layer run.
  bool usable = compiled || (relaxed > 0 && sink->error_count() + sink->dropped() == errors_before);

  // The strictness layer reads the whole AST: glslang's link drops uncalled functions.
  FragmentOutputWrites fragment_writes;
  StrictContext ctx{stage,
                    sources,
                    sink,
                    *shader.getIntermediate(),
                    options.link,
                    /*linked=*/false,
                    options.link_as_program,
                    &fragment_writes};
  if (usable) RunStrictChecks(ctx);

  glslang::TProgram program;
  if (usable && options.link) {
    program.addShader(&shader);
    int errors_before_link = sink->error_count() + sink->dropped();
    bool linked = program.link(kMessages);
    int relaxed_link = ReportInfoLog(program.getInfoLog(), sources, stage, /*link=*/true, sink);
    ctx.linked =
        linked || (relaxed_link > 0 && sink->error_count() + sink->dropped() == errors_before_link);
    RunLinkStrictChecks(ctx);
  }
  if (!usable && sink->error_count() + sink->dropped() == errors_before) {
    // glslang refused the shader without saying why: never report success.
    sink->Report(Info(Diag::InternalError), sources.front(), {0, 0},
                 "glslang rejected the shader without a message");
  }
  result.ok = sink->error_count() + sink->dropped() == errors_before;
  return result;
}

}  // namespace arbiter::glsl
