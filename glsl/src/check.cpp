// CheckShader: glslang compile (and link) of one GLSL 1.10 or 1.20 shader, its info log turned
// into arbiter diagnostics, then arbiter's own rules of that version.
#include "arbiter/glsl/check.h"

#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <string>

#include "diag.h"
#include "info_log.h"
#include "prepare.h"
#include "scan.h"
#include "strict/strict.h"

namespace arbiter::glsl {
namespace {

// Every error, not only the first (EShMsgCascadingErrors).
constexpr auto kMessages = static_cast<EShMessages>(EShMsgCascadingErrors);

bool EndsWith(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

// File name endings and their stages; the longest match wins (".vert.glsl" before ".glsl").
struct StageSuffix {
  std::string_view suffix;
  std::optional<Stage> stage;
};
constexpr StageSuffix kSuffixes[] = {
    {".vert.glsl", Stage::Vertex}, {".frag.glsl", Stage::Fragment}, {".vert", Stage::Vertex},
    {".vs", Stage::Vertex},        {".vsh", Stage::Vertex},         {".frag", Stage::Fragment},
    {".fs", Stage::Fragment},      {".fsh", Stage::Fragment},       {".glsl", std::nullopt},
};

const StageSuffix* SuffixOf(std::string_view path) {
  for (const StageSuffix& s : kSuffixes) {
    if (EndsWith(path, s.suffix)) return &s;
  }
  return nullptr;
}

int Errors(const compiler::DiagnosticSink& sink) { return sink.error_count() + sink.dropped(); }

}  // namespace

std::optional<Stage> StageFromPath(std::string_view path) {
  const StageSuffix* s = SuffixOf(path);
  return s != nullptr ? s->stage : std::nullopt;
}

bool IsGlslPath(std::string_view path) { return SuffixOf(path) != nullptr; }

CheckResult CheckShader(Stage stage, const std::vector<const compiler::SourceFile*>& sources,
                        const CheckOptions& options, compiler::DiagnosticSink* sink) {
  EnsureGlslang();
  CheckResult result;
  const int errors_before = Errors(*sink);
  if (sources.empty()) return result;

  PreparedShader prepared = PrepareShader(stage, sources, options, sink);
  if (!prepared.checked) return result;
  bool compiled = false;
  std::unique_ptr<glslang::TShader> shader = ParsePrepared(stage, &prepared, &compiled);
  InfoLogContext log{prepared.files, stage, prepared.version, options.link, &prepared};
  int relaxed = ReportInfoLog(shader->getInfoLog(), log, /*link=*/false, sink);
  // Only errors that the shader's version does not make (see info_log.cpp): glslang recovered
  // from each of them, so its AST is the shader's and the link step and the strictness layer
  // run.
  bool usable = compiled || (relaxed > 0 && Errors(*sink) == errors_before);

  // The strictness layer reads the whole AST: glslang's link drops uncalled functions.
  FragmentOutputWrites fragment_writes;
  StrictContext ctx{stage,
                    prepared.version,
                    prepared.gpu4(),
                    prepared.files,
                    sink,
                    *shader->getIntermediate(),
                    options.link,
                    /*linked=*/false,
                    &fragment_writes,
                    prepared.preamble,
                    prepared.renames};
  if (usable) RunStrictChecks(ctx);
  // Chapter 9: "translation_unit: external_declaration | translation_unit
  // external_declaration"; glslang takes a shader without any.
  if (usable && std::all_of(prepared.texts.begin(), prepared.texts.end(),
                            [](const std::string& t) { return Tokenize(t).empty(); })) {
    sink->Report(Info(Diag::SyntaxError), sources.front(), {0, 0},
                 "the shader has no declaration: a shader is one or more declarations and "
                 "function definitions (chapter 9 grammar: translation_unit)");
  }

  // The link step runs for a shader object too: it finds recursion, which drivers reject at
  // compile time (glslang only when linking); what only a program needs (main(), the bodies
  // of called functions) is dropped from its messages when compiling (info_log.cpp).
  glslang::TProgram program;
  if (usable) {
    program.addShader(shader.get());
    int errors_before_link = Errors(*sink);
    bool linked = program.link(kMessages);
    int relaxed_link = ReportInfoLog(program.getInfoLog(), log, /*link=*/true, sink);
    ctx.linked = linked || (relaxed_link > 0 && Errors(*sink) == errors_before_link);
    RunLinkStrictChecks(ctx);
  }
  if (!usable && Errors(*sink) == errors_before) {
    // glslang refused the shader without saying why: never report success.
    sink->Report(Info(Diag::InternalError), sources.front(), {0, 0},
                 "glslang rejected the shader without a message");
  }
  result.ok = Errors(*sink) == errors_before;
  result.included = std::move(prepared.included);
  return result;
}

}  // namespace arbiter::glsl
