// arbiter check: validate every input and report its diagnostics.
#include "arbiter/arbvp/check.h"
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
  for (const Input& input : ExpandInputs(options.files)) {
    compiler::FileReport report;
    report.path = input.display_path;
    std::unique_ptr<compiler::SourceFile> source = ReadInput(input, &report);
    if (!source) {
      exit = Worse(exit, Exit::Environment);
      reports.push_back(std::move(report));
      continue;
    }
    compiler::DiagnosticSink sink(options.error_limit);
    arbvp::CheckProgram(*source, check_options, &sink);
    if (options.werror) sink.PromoteWarnings();
    if (sink.error_count() > 0) exit = Worse(exit, Exit::Rejected);
    report.diagnostics = std::move(sink.diagnostics());
    report.dropped_errors = sink.dropped();
    reports.push_back(std::move(report));
    sources.push_back(std::move(source));
  }
  PrintReports(reports, options);
  return static_cast<int>(exit);
}

}  // namespace arbiter::cli
