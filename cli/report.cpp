// Printing diagnostics in the chosen format.
#include <fmt/format.h>
#include <sys/uio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

#include "cli.h"

namespace arbiter::cli {
namespace {

bool UseColor(const std::string& mode) {
  if (mode == "always") return true;
  if (mode == "never") return false;
  const char* term = std::getenv("TERM");
  return isatty(fileno(stderr)) && std::getenv("NO_COLOR") == nullptr && term != nullptr &&
         std::string_view(term) != "dumb";
}

}  // namespace

compiler::TextOptions TextOptionsFor(const CommonOptions& options) {
  compiler::TextOptions text;
  text.color = UseColor(options.color);
  return text;
}

void PrintText(const std::vector<std::string>& rendered) {
  // Gathered writes: stderr is unbuffered, a write per file costs more than rendering it,
  // and joining a big batch's text first cost a fresh buffer as large as all of it.
  std::fflush(stderr);
  std::vector<iovec> parts;
  parts.reserve(rendered.size());
  for (const std::string& text : rendered) {
    if (!text.empty()) parts.push_back({const_cast<char*>(text.data()), text.size()});
  }
  size_t next = 0;
  while (next < parts.size()) {
    const int count = static_cast<int>(std::min<size_t>(parts.size() - next, IOV_MAX));
    ssize_t written = writev(STDERR_FILENO, &parts[next], count);
    if (written < 0) {
      if (errno == EINTR) continue;
      break;  // stderr closed or full: as fwrite, nothing more to do
    }
    for (; next < parts.size() && static_cast<size_t>(written) >= parts[next].iov_len; ++next) {
      written -= static_cast<ssize_t>(parts[next].iov_len);
    }
    if (written > 0) {
      parts[next].iov_base = static_cast<char*>(parts[next].iov_base) + written;
      parts[next].iov_len -= static_cast<size_t>(written);
    }
  }
  std::fflush(stdout);
}

void PrintReports(const std::vector<compiler::FileReport>& reports, const CommonOptions& options) {
  if (options.format == "json") {
    std::fputs(compiler::RenderJson(reports).c_str(), stdout);
  } else if (options.format == "sarif") {
    std::fputs(compiler::RenderSarif(reports, ARBITER_VERSION).c_str(), stdout);
  } else {
    const compiler::TextOptions text = TextOptionsFor(options);
    std::vector<std::string> rendered;
    rendered.reserve(reports.size());
    for (const compiler::FileReport& report : reports) {
      rendered.push_back(compiler::RenderText(report, text));
    }
    PrintText(rendered);
    return;
  }
  std::fflush(stdout);
}

nlohmann::ordered_json DiagnosticsJson(const std::vector<compiler::FileReport>& reports) {
  if (reports.empty()) return nlohmann::ordered_json::array();
  return nlohmann::ordered_json::parse(compiler::RenderJson(reports))["files"];
}

void DistributeDiagnostics(compiler::DiagnosticSink* sink,
                           const std::vector<std::unique_ptr<compiler::SourceFile>>& keep,
                           std::vector<compiler::FileReport>* reports) {
  for (compiler::Diagnostic& d : sink->diagnostics()) {
    size_t index = 0;
    for (size_t i = 0; i < keep.size(); ++i) {
      if (keep[i].get() == d.file) index = i;
    }
    (*reports)[index].diagnostics.push_back(std::move(d));
  }
  reports->front().dropped_errors = sink->dropped();
}

}  // namespace arbiter::cli
