// JSON renderer: one deterministic document for the diagnostics of many files.
#include <string>

#include "arbiter/compiler/render.h"
#include "nlohmann/json.hpp"
#include "render_common.h"

namespace arbiter::compiler {
namespace {

using Json = nlohmann::ordered_json;

// Location fields of a diagnostic or note; null when it has no file.
void AddLocation(Json* object, const SourceFile* file, Range range, bool with_end) {
  if (file == nullptr) {
    (*object)["line"] = nullptr;
    (*object)["column"] = nullptr;
    if (with_end) {
      (*object)["end_line"] = nullptr;
      (*object)["end_column"] = nullptr;
    }
    (*object)["offset"] = nullptr;
    if (with_end) {
      (*object)["length"] = nullptr;
    }
    return;
  }
  const ResolvedRange resolved = Resolve(*file, range);
  (*object)["line"] = resolved.begin.line;
  (*object)["column"] = resolved.begin.column;
  if (with_end) {
    (*object)["end_line"] = resolved.end.line;
    (*object)["end_column"] = resolved.end.column;
  }
  (*object)["offset"] = resolved.offset;
  if (with_end) {
    (*object)["length"] = resolved.length;
  }
}

Json DiagnosticJson(const FileReport& report, const Diagnostic& diag) {
  Json object = Json::object();
  if (diag.info != nullptr) {
    object["code"] = diag.info->code;
  } else {
    object["code"] = nullptr;
  }
  object["severity"] = SeverityName(diag.severity);
  object["message"] = diag.message;
  // A diagnostic about another file than the report's (a linked stage, say) names it.
  const std::string_view path = PathOf(report, diag.file, diag.path);
  if (path != report.path) {
    object["path"] = path;
  }
  AddLocation(&object, diag.file, diag.range, /*with_end=*/true);
  Json notes = Json::array();
  for (const Note& note : diag.notes) {
    Json note_object = Json::object();
    note_object["message"] = note.message;
    if (note.file != nullptr && note.file->path() != report.path) {
      note_object["path"] = note.file->path();
    }
    AddLocation(&note_object, note.file, note.range, /*with_end=*/false);
    notes.push_back(std::move(note_object));
  }
  object["notes"] = std::move(notes);
  return object;
}

}  // namespace

std::string RenderJson(const std::vector<FileReport>& reports) {
  Json files = Json::array();
  int total_errors = 0;
  int total_warnings = 0;
  for (const FileReport& report : reports) {
    int errors = report.dropped_errors;
    int warnings = 0;
    Json diagnostics = Json::array();
    for (const Diagnostic* d : InPositionOrder(report)) {
      const Diagnostic& diag = *d;
      errors += diag.severity == Severity::Error ? 1 : 0;
      warnings += diag.severity == Severity::Warning ? 1 : 0;
      diagnostics.push_back(DiagnosticJson(report, diag));
    }
    Json file = Json::object();
    file["path"] = report.path;
    file["errors"] = errors;
    file["warnings"] = warnings;
    file["dropped_errors"] = report.dropped_errors;
    file["diagnostics"] = std::move(diagnostics);
    files.push_back(std::move(file));
    total_errors += errors;
    total_warnings += warnings;
  }
  Json document = Json::object();
  document["files"] = std::move(files);
  document["summary"] = {
      {"files", reports.size()}, {"errors", total_errors}, {"warnings", total_warnings}};
  // Invalid UTF-8 (a message quoting a broken comment, say) becomes U+FFFD instead of
  // throwing.
  return document.dump(2, ' ', /*ensure_ascii=*/false, Json::error_handler_t::replace) + "\n";
}

}  // namespace arbiter::compiler
