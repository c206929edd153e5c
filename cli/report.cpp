// Printing diagnostics in the chosen format.
#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
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
  // One write: stderr is unbuffered, and a write per file costs more than rendering it.
  std::string out;
  for (const std::string& text : rendered) out += text;
  std::fwrite(out.data(), 1, out.size(), stderr);
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

}  // namespace arbiter::cli
