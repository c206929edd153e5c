#include "load_arb.h"

#include <fmt/format.h>

namespace arbiter::cli {
namespace {

// Whether an input that is no ARB program is a GLSL shader: by its name, or by its text.
bool LooksLikeGlsl(const Input& input, std::string_view text) {
  if (glsl::StageFromPath(input.path)) return true;
  for (std::string_view word : {"#version", "void main", "gl_Position", "gl_FragColor"}) {
    if (text.find(word) != std::string_view::npos) return true;
  }
  return false;
}

}  // namespace

Exit LoadArbPrograms(const CommonOptions& options, std::string_view command,
                     std::vector<LoadedArb>* loaded, std::vector<compiler::FileReport>* reports) {
  std::optional<arbvp::ProgramKind> stage;
  if (!ResolveStage(options, &stage)) return Exit::Usage;
  std::optional<compiler::LimitProfile> profile;
  if (!ResolveLimits(options, &profile)) return Exit::Usage;
  Exit exit = Exit::Ok;
  for (const Input& input : ExpandInputs(options.files, ResolveJobs(options))) {
    // A directory may hold GLSL shaders beside the ARB programs: those are check's alone.
    if (input.found && glsl::StageFromPath(input.path)) continue;
    compiler::FileReport report;
    report.path = input.display_path;
    std::unique_ptr<compiler::SourceFile> source = ReadInput(input, &report);  // takes the bytes
    LoadedArb l{input, std::move(source), {}};
    if (!l.source) {
      exit = Worse(exit, Exit::Environment);
    } else {
      compiler::DiagnosticSink sink(options.error_limit);
      arbvp::CheckOptions check;
      check.expected_kind = stage;
      check.profile = profile ? &*profile : nullptr;
      l.checked = arbvp::CheckProgram(*l.source, check, &sink);
      if (options.werror) sink.PromoteWarnings();
      l.rejected = !l.checked.ok || !l.checked.program || sink.error_count() > 0;
      if (l.rejected) exit = Worse(exit, Exit::Rejected);
      report.diagnostics = std::move(sink.diagnostics());
      report.dropped_errors = sink.dropped();
      const std::string_view text = l.source->text();
      if (!arbvp::LooksLikeArbProgram(text) && !report.diagnostics.empty() &&
          LooksLikeGlsl(input, text)) {
        report.diagnostics.front().notes.push_back(
            {nullptr,
             {},
             command == "verify"
                 ? std::string("this is a GLSL shader: 'arbiter verify' takes it named by its "
                               "stage (.vert, .frag, ...)")
                 : fmt::format("this is a GLSL shader: 'arbiter {}' takes ARB programs; "
                               "'arbiter check', 'info', 'link', 'exec', 'verify' and 'run' "
                               "take GLSL",
                               command)});
      }
      loaded->push_back(std::move(l));
    }
    if (!report.diagnostics.empty()) reports->push_back(std::move(report));
  }
  return exit;
}

void PrintLoadReports(const std::vector<compiler::FileReport>& reports,
                      const CommonOptions& options) {
  if (reports.empty()) return;
  CommonOptions text = options;
  text.format = "text";
  PrintReports(reports, text);
}

}  // namespace arbiter::cli
