// Diagnostics as plain data, and the sink libraries report into (they never print).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/compiler/source.h"

namespace arbiter::compiler {

enum class Severity : uint8_t { Note, Warning, Error };

// Static facts about one diagnostic kind: one row of a library's diagnostics.def table.
struct DiagnosticInfo {
  std::string_view code;      // stable kebab-case code, e.g. "arb-decl-redeclared"
  Severity severity;          // default severity
  std::string_view summary;   // one-line description (SARIF rule text, docs)
  std::string_view spec_ref;  // the specification clause that decides it ("" if none)
};

struct Note {
  const SourceFile* file = nullptr;  // may be null: a note without a location
  Range range;
  std::string message;
};

struct Diagnostic {
  const DiagnosticInfo* info = nullptr;
  Severity severity = Severity::Error;
  const SourceFile* file = nullptr;  // may be null for file-less diagnostics (I/O)
  Range range;
  std::string message;
  std::vector<Note> notes;
  // For file-less diagnostics: the path they concern.
  std::string path;
};

// Collects diagnostics in order. `error_limit` > 0 stops recording errors past the limit;
// the renderers then add a final note that says so. Once `error_limit` errors are stored,
// every later diagnostic is dropped: errors are counted in dropped(), later warnings and
// notes are neither stored nor counted (a later PromoteWarnings() counts the warnings as
// dropped errors). error_count() counts stored errors only.
// What -W<code>, -Wno-<code> and -Werror=<code> ask of one warning code.
enum class WarningAction { Default, Off, Error };

// The command line's warning switches: -Werror, and per code.
struct WarningPolicy {
  bool werror = false;
  std::map<std::string, WarningAction, std::less<>> codes;
};

class DiagnosticSink {
 public:
  explicit DiagnosticSink(int error_limit = 0) : error_limit_(error_limit) {}

  // Records a diagnostic with the info's default severity. Returns the stored diagnostic
  // so the caller can add notes (nullptr when dropped by the error limit); the pointer is
  // valid until the next Report or PromoteWarnings.
  Diagnostic* Report(const DiagnosticInfo& info, const SourceFile* file, Range range,
                     std::string message);
  // Same, with an explicit severity (a warning promoted to an error, say).
  Diagnostic* Report(const DiagnosticInfo& info, Severity severity, const SourceFile* file,
                     Range range, std::string message);

  const std::vector<Diagnostic>& diagnostics() const { return diags_; }
  std::vector<Diagnostic>& diagnostics() { return diags_; }
  int error_count() const { return errors_; }
  int warning_count() const { return warnings_; }
  // True when errors were dropped because of the error limit.
  bool limit_reached() const { return dropped_ > 0; }
  int dropped() const { return dropped_; }
  // Promotes every warning to an error (-Werror). The error limit is applied again in
  // report order, as if the warnings had been reported as errors: promoted or original
  // errors past the limit are removed and counted in dropped().
  void PromoteWarnings();
  // Applies -Wno-<code> (the warning is removed), -Werror=<code> and -Werror (promoted), in
  // report order with the error limit, as PromoteWarnings does.
  void ApplyWarningPolicy(const WarningPolicy& policy);

 private:
  int error_limit_ = 0;
  int errors_ = 0;
  int warnings_ = 0;
  int dropped_ = 0;
  int dropped_warnings_ = 0;  // warnings dropped after the limit (errors if promoted)
  std::vector<Diagnostic> diags_;
};

// "error", "warning" or "note".
std::string_view SeverityName(Severity severity);

}  // namespace arbiter::compiler
