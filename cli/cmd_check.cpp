// arbiter check: validate every input (ARB programs and GLSL shaders) and report its
// diagnostics.
#include "arbiter/arbvp/check.h"
#include "arbiter/glsl/check.h"
#include "cli.h"

namespace arbiter::cli {

int RunCheck(const CommonOptions& options) {
  std::optional<compiler::LimitProfile> profile;
  std::optional<arbvp::ProgramKind> stage;
  if (!ResolveLimits(options, &profile) || !ResolveStage(options, &stage)) {
    return static_cast<int>(Exit::Usage);
  }
  arbvp::CheckOptions check_options;
  check_options.profile = profile ? &*profile : nullptr;
  check_options.expected_kind = stage;

  Exit exit = Exit::Ok;
  std::vector<compiler::FileReport> reports;
  // Sources stay alive until rendering: diagnostics point into them.
  std::vector<std::unique_ptr<compiler::SourceFile>> sources;
  std::vector<Input> inputs = ExpandInputs(options.files);
  // With --stage vert|frag, the files are the strings of one shader, in order.
  bool one_shader = options.stage == "vert" || options.stage == "frag";
  std::vector<const compiler::SourceFile*> shader_strings;
  for (const Input& input : inputs) {
    compiler::FileReport report;
    report.path = input.display_path;
    std::unique_ptr<compiler::SourceFile> source = ReadInput(input, &report);
    if (!source) {
      exit = Worse(exit, Exit::Environment);
      reports.push_back(std::move(report));
      continue;
    }
    if (one_shader) {
      shader_strings.push_back(source.get());
      sources.push_back(std::move(source));
      continue;
    }
    compiler::DiagnosticSink sink(options.error_limit);
    if (std::optional<glsl::Stage> glsl_stage = GlslStage(options, input)) {
      glsl::CheckShader(*glsl_stage, {source.get()}, glsl::CheckOptions{}, &sink);
    } else {
      arbvp::CheckProgram(*source, check_options, &sink);
    }
    if (options.werror) sink.PromoteWarnings();
    if (sink.error_count() > 0) exit = Worse(exit, Exit::Rejected);
    report.diagnostics = std::move(sink.diagnostics());
    report.dropped_errors = sink.dropped();
    reports.push_back(std::move(report));
    sources.push_back(std::move(source));
  }
  if (one_shader && !shader_strings.empty()) {
    compiler::FileReport report;
    report.path = shader_strings.front()->path();
    compiler::DiagnosticSink sink(options.error_limit);
    glsl::CheckShader(options.stage == "vert" ? glsl::Stage::Vertex : glsl::Stage::Fragment,
                      shader_strings, glsl::CheckOptions{}, &sink);
    if (options.werror) sink.PromoteWarnings();
    if (sink.error_count() > 0) exit = Worse(exit, Exit::Rejected);
    report.diagnostics = std::move(sink.diagnostics());
    report.dropped_errors = sink.dropped();
    reports.push_back(std::move(report));
  }
  PrintReports(reports, options);
  return static_cast<int>(exit);
}

}  // namespace arbiter::cli
