// DiagnosticSink: ordered collection of diagnostics with an error limit and -Werror.
#include "arbiter/compiler/diagnostic.h"

#include <utility>

namespace arbiter::compiler {

Diagnostic* DiagnosticSink::Report(const DiagnosticInfo& info, const SourceFile* file, Range range,
                                   std::string message) {
  return Report(info, info.severity, file, range, std::move(message));
}

Diagnostic* DiagnosticSink::Report(const DiagnosticInfo& info, Severity severity,
                                   const SourceFile* file, Range range, std::string message) {
  if (error_limit_ > 0 && errors_ >= error_limit_) {
    if (severity == Severity::Error) {
      ++dropped_;
    } else if (severity == Severity::Warning) {
      ++dropped_warnings_;
    }
    return nullptr;
  }
  if (severity == Severity::Error) {
    ++errors_;
  } else if (severity == Severity::Warning) {
    ++warnings_;
  }
  Diagnostic& diag = diags_.emplace_back();
  diag.info = &info;
  diag.severity = severity;
  diag.file = file;
  diag.range = range;
  diag.message = std::move(message);
  return &diag;
}

void DiagnosticSink::PromoteWarnings() {
  WarningPolicy all;
  all.werror = true;
  ApplyWarningPolicy(all);
}

void DiagnosticSink::ApplyWarningPolicy(const WarningPolicy& policy) {
  if (!policy.werror && policy.codes.empty()) return;
  // Replay the stored diagnostics in order with the policy's severities, applying the limit.
  std::vector<Diagnostic> kept;
  kept.reserve(diags_.size());
  int errors = 0;
  int warnings = 0;
  for (Diagnostic& diag : diags_) {
    if (diag.severity == Severity::Warning) {
      const auto it =
          diag.info != nullptr ? policy.codes.find(diag.info->code) : policy.codes.end();
      const WarningAction action = it != policy.codes.end() ? it->second : WarningAction::Default;
      if (action == WarningAction::Off) continue;
      if (action == WarningAction::Error || policy.werror) diag.severity = Severity::Error;
    }
    if (error_limit_ > 0 && errors >= error_limit_) {
      if (diag.severity == Severity::Error) {
        ++dropped_;
      }
      continue;
    }
    if (diag.severity == Severity::Error) {
      ++errors;
    } else if (diag.severity == Severity::Warning) {
      ++warnings;
    }
    kept.push_back(std::move(diag));
  }
  diags_ = std::move(kept);
  errors_ = errors;
  warnings_ = warnings;
  if (policy.werror) {
    dropped_ += dropped_warnings_;
    dropped_warnings_ = 0;
  }
}

std::string_view SeverityName(Severity severity) {
  switch (severity) {
    case Severity::Note:
      return "note";
    case Severity::Warning:
      return "warning";
    case Severity::Error:
      return "error";
  }
  return "error";
}

}  // namespace arbiter::compiler
