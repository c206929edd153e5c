#include "load_arb.h"

namespace arbiter::cli {

Exit LoadArbPrograms(const CommonOptions& options, std::vector<LoadedArb>* loaded) {
  std::optional<arbvp::ProgramKind> stage;
  if (!ResolveStage(options, &stage)) return Exit::Usage;
  std::optional<compiler::LimitProfile> profile;
  if (!ResolveLimits(options, &profile)) return Exit::Usage;
  std::vector<compiler::FileReport> reports;
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
      if (!l.checked.ok || !l.checked.program || sink.error_count() > 0) {
        exit = Worse(exit, Exit::Rejected);
      }
      report.diagnostics = std::move(sink.diagnostics());
      report.dropped_errors = sink.dropped();
      loaded->push_back(std::move(l));
    }
    if (!report.diagnostics.empty()) reports.push_back(std::move(report));
  }
  CommonOptions text = options;
  text.format = "text";
  if (!reports.empty()) PrintReports(reports, text);
  return exit;
}

}  // namespace arbiter::cli
