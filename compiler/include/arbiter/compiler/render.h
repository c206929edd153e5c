// Renderers of diagnostics: text (terminal and logs), JSON and SARIF 2.1.0.
#pragma once

#include <string>
#include <vector>

#include "arbiter/compiler/diagnostic.h"

namespace arbiter::compiler {

// The diagnostics of one input file, as renderers take them.
struct FileReport {
  std::string path;  // as given on the command line
  std::vector<Diagnostic> diagnostics;
  int dropped_errors = 0;  // errors not shown because of --error-limit
};

struct TextOptions {
  bool color = false;       // ANSI colour (only when writing to a terminal)
  bool show_source = true;  // the source line and a caret line under the range
};

// `path:line:col: error: message [code]`, the source line (tabs expanded to 8 columns,
// long lines clipped around the column) and `^~~~` under the range; notes likewise
// (`note: message` alone for a note without a file). A diagnostic without a file prints
// `path: error: message [code]`. Ends with `path: note: N more errors not shown
// (--error-limit)` when errors were dropped.
std::string RenderText(const FileReport& report, const TextOptions& options);

// One JSON document for many files, 2-space indented, keys in this order:
// {"files":[{"path", "errors", "warnings", "dropped_errors",
//   "diagnostics":[{"code","severity","message","line","column","end_line","end_column",
//                   "offset","length","notes":[{"message","line","column","offset"}]}]}],
//  "summary":{"files","errors","warnings"}}
// "errors" counts dropped errors too. Positions are null without a file; a diagnostic or
// note in another file than the report's also has "path" (after "message").
std::string RenderJson(const std::vector<FileReport>& reports);

// SARIF 2.1.0 with one run, the tool "arbiter", rules for every code used (id = code,
// shortDescription = summary, help = summary and spec clause as text and markdown, helpUri =
// its docs/diagnostics.md entry), results with physical locations (1-based line/column,
// byteOffset) and related locations for notes. columnKind is "unicodeCodePoints"; dropped
// errors are reported as a tool execution notification.
std::string RenderSarif(const std::vector<FileReport>& reports, const std::string& tool_version);

}  // namespace arbiter::compiler
