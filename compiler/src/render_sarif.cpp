// SARIF 2.1.0 renderer: one run of the tool "arbiter", a rule per code, a result per diagnostic.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

#include "arbiter/compiler/render.h"
#include "fmt/format.h"
#include "nlohmann/json.hpp"
#include "render_common.h"

namespace arbiter::compiler {
namespace {

using Json = nlohmann::ordered_json;

constexpr std::string_view kSchema = "https://json.schemastore.org/sarif-2.1.0.json";
constexpr std::string_view kInformationUri = "https://github.com/arbiter-shaders/arbiter";
// helpUri must be an absolute URI (SARIF 2.1.0 3.49.12; the SARIF validator rejects a
// relative "docs/diagnostics.md#code"): the documentation page in the repository.
constexpr std::string_view kHelpUriBase =
    "https://github.com/arbiter-shaders/arbiter/blob/main/docs/diagnostics.md#";

// SARIF levels have the same names as our severities.
std::string_view Level(Severity severity) { return SeverityName(severity); }

// A path as a URI reference: forward slashes, and percent-encoding for the bytes a URI
// cannot hold (space, '%', '#', '?', non-ASCII, ...).
std::string PathToUri(std::string_view path) {
  std::string uri;
  for (const char c : path) {
    const auto byte = static_cast<uint8_t>(c);
    const bool plain = (byte >= 'a' && byte <= 'z') || (byte >= 'A' && byte <= 'Z') ||
                       (byte >= '0' && byte <= '9') ||
                       std::string_view("-._~/:@!$&'()*+,;=").find(c) != std::string_view::npos;
    if (c == '\\') {
      uri += '/';
    } else if (plain) {
      uri += c;
    } else {
      uri += fmt::format("%{:02X}", byte);
    }
  }
  return uri;
}

// {"physicalLocation": {"artifactLocation": {"uri"}, "region": {...}}}; no region without
// a file.
Json PhysicalLocation(std::string_view path, const SourceFile* file, Range range) {
  Json physical = Json::object();
  physical["artifactLocation"] = {{"uri", PathToUri(path)}};
  if (file != nullptr) {
    const ResolvedRange resolved = Resolve(*file, range);
    physical["region"] = {
        {"startLine", resolved.begin.line}, {"startColumn", resolved.begin.column},
        {"endLine", resolved.end.line},     {"endColumn", resolved.end.column},
        {"byteOffset", resolved.offset},    {"byteLength", resolved.length}};
  }
  return Json{{"physicalLocation", std::move(physical)}};
}

// Text as Markdown shows it: grammar symbols such as '<instruction>' would otherwise be taken
// for HTML tags (and dropped), '_SAT' or '[n]' for emphasis or links.
std::string MarkdownEscape(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (std::string_view("\\`*_[]<>#").find(c) != std::string_view::npos) {
      out += '\\';
    }
    out += c;
  }
  return out;
}

// The rule's help, as docs/diagnostics.md words the entry (severity, summary, spec clause)
// plus a link to it: code-scanning services show it beside each result.
Json Help(const DiagnosticInfo& info, std::string_view help_uri) {
  const std::string_view severity = SeverityName(info.severity);
  std::string text = fmt::format("{}: {}.", severity, info.summary);
  std::string markdown = fmt::format("**{}**: {}.", severity, MarkdownEscape(info.summary));
  if (!info.spec_ref.empty()) {
    text += fmt::format(" Spec: {}.", info.spec_ref);
    markdown += fmt::format(" Spec: {}.", MarkdownEscape(info.spec_ref));
  }
  text += fmt::format(" Documentation: {}", help_uri);
  markdown += fmt::format("\n\n[`{}` in arbiter's diagnostics]({})", info.code, help_uri);
  return Json{{"text", std::move(text)}, {"markdown", std::move(markdown)}};
}

Json Rule(const DiagnosticInfo& info) {
  std::string full(info.summary);
  if (!info.spec_ref.empty()) {
    full += fmt::format(" ({})", info.spec_ref);
  }
  const std::string help_uri = fmt::format("{}{}", kHelpUriBase, info.code);
  Json rule = Json::object();
  rule["id"] = info.code;
  rule["shortDescription"] = {{"text", info.summary}};
  rule["fullDescription"] = {{"text", full}};
  rule["help"] = Help(info, help_uri);
  rule["helpUri"] = help_uri;
  rule["defaultConfiguration"] = {{"level", Level(info.severity)}};
  return rule;
}

}  // namespace

std::string RenderSarif(const std::vector<FileReport>& reports, const std::string& tool_version) {
  Json rules = Json::array();
  std::map<std::string_view, size_t> rule_index;  // code -> index in `rules`
  Json results = Json::array();
  Json notifications = Json::array();

  for (const FileReport& report : reports) {
    for (const Diagnostic* d : InPositionOrder(report)) {
      const Diagnostic& diag = *d;
      Json result = Json::object();
      if (diag.info != nullptr) {
        auto [it, added] = rule_index.try_emplace(diag.info->code, rules.size());
        if (added) {
          rules.push_back(Rule(*diag.info));
        }
        result["ruleId"] = diag.info->code;
        result["ruleIndex"] = it->second;
      }
      result["level"] = Level(diag.severity);
      result["message"] = {{"text", diag.message}};
      result["locations"] = Json::array(
          {PhysicalLocation(PathOf(report, diag.file, diag.path), diag.file, diag.range)});
      if (!diag.notes.empty()) {
        Json related = Json::array();
        for (const Note& note : diag.notes) {
          Json location = Json::object();
          if (note.file != nullptr) {
            location = PhysicalLocation(note.file->path(), note.file, note.range);
          }
          location["message"] = {{"text", note.message}};
          related.push_back(std::move(location));
        }
        result["relatedLocations"] = std::move(related);
      }
      results.push_back(std::move(result));
    }
    if (report.dropped_errors > 0) {
      Json notification = Json::object();
      notification["level"] = "note";
      notification["message"] = {
          {"text", fmt::format("{} more error{} not shown (--error-limit)", report.dropped_errors,
                               report.dropped_errors == 1 ? "" : "s")}};
      notification["locations"] = Json::array({PhysicalLocation(report.path, nullptr, {})});
      notifications.push_back(std::move(notification));
    }
  }

  Json driver = Json::object();
  driver["name"] = "arbiter";
  driver["version"] = tool_version;
  driver["informationUri"] = kInformationUri;
  driver["rules"] = std::move(rules);

  Json run = Json::object();
  run["tool"] = {{"driver", std::move(driver)}};
  if (!notifications.empty()) {
    // Errors past --error-limit are not results; say so where SARIF viewers look.
    run["invocations"] = Json::array(
        {{{"executionSuccessful", true}, {"toolExecutionNotifications", notifications}}});
  }
  // Our columns count characters (Unicode code points), not UTF-16 code units.
  run["columnKind"] = "unicodeCodePoints";
  run["results"] = std::move(results);

  Json document = Json::object();
  document["$schema"] = kSchema;
  document["version"] = "2.1.0";
  document["runs"] = Json::array({std::move(run)});
  return document.dump(2, ' ', /*ensure_ascii=*/false, Json::error_handler_t::replace) + "\n";
}

}  // namespace arbiter::compiler
