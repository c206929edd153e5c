// --driver-check: compiles each GLSL input with Mesa too and notes where Mesa disagrees.
#include "driver_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <mutex>
#include <regex>
#include <string>

#include "arbiter/runtime/mesa.h"

namespace arbiter::cli {
namespace {

// Not rows of glsl/src/diagnostics.def: these concern the driver, not the GLSL language.
const compiler::DiagnosticInfo kDriverCheckDiffers{
    "driver-check-differs", compiler::Severity::Note,
    "Mesa's verdict on the shader (--driver-check) differs from arbiter's", ""};
const compiler::DiagnosticInfo kRuntimeGlError{
    "runtime-gl-error", compiler::Severity::Error,
    "a GL call of --driver-check failed, so Mesa's verdict is unknown", ""};

// The one Mesa context of the process, created at the first --driver-check input.
struct SharedMesa {
  std::once_flag once;
  std::unique_ptr<runtime::MesaContext> context;  // null when it could not be created
};

SharedMesa& Shared() {
  static SharedMesa shared;
  return shared;
}

runtime::MesaContext* GetMesa(const std::string& driver) {
  SharedMesa& shared = Shared();
  std::call_once(shared.once, [&] {
    runtime::MesaOptions options;
    options.driver = driver;
    std::string error;
    shared.context = runtime::CreateMesaContext(options, &error);
    if (shared.context == nullptr) {
      fmt::print(stderr, "arbiter: error: --driver-check: cannot start Mesa ({}): {}\n", driver,
                 error);
    }
  });
  return shared.context.get();
}

bool ArbiterAccepts(const compiler::FileReport& report) {
  if (report.dropped_errors > 0) return false;
  return std::none_of(
      report.diagnostics.begin(), report.diagnostics.end(),
      [](const compiler::Diagnostic& d) { return d.severity == compiler::Severity::Error; });
}

// Where Mesa's message points: "S:L(C): ..." names line L of the strings joined in order
// (Mesa joins them before compiling). Only the line is used: Mesa's column counts the
// preprocessed text, whose blanks are squeezed. The location is the first non-blank character
// of that line; false when the message has no position or it lies outside the sources.
bool LocateMesaMessage(const std::string& message,
                       const std::vector<const compiler::SourceFile*>& sources,
                       const compiler::SourceFile** file, compiler::Range* range) {
  static const std::regex kPosition(R"(^(\d+):(\d+)\((\d+)\):)");
  std::smatch m;
  if (!std::regex_search(message, m, kPosition)) return false;
  unsigned long line = std::stoul(m[2].str());
  if (line == 0 || line > 0xffffffffUL) return false;
  // Walk the strings as one text: a string that does not end with a new-line shares its
  // last line with the next string.
  uint32_t current = 1;
  for (const compiler::SourceFile* source : sources) {
    const uint32_t first = current;
    const uint32_t last = first + source->line_count() - 1;
    if (line <= last) {
      const uint32_t local = static_cast<uint32_t>(line - first + 1);
      const std::string_view text = source->LineText(local);
      const size_t blank = std::min(text.find_first_not_of(" \t\f\v"), text.size());
      const uint32_t begin = source->LineStart(local) + static_cast<uint32_t>(blank);
      *file = source;
      *range = {begin, blank < text.size() ? begin + 1 : begin};
      return true;
    }
    const std::string& bytes = source->text();
    const bool ends_line = !bytes.empty() && (bytes.back() == '\n' || bytes.back() == '\r');
    current = ends_line ? last + 1 : last;
  }
  return false;
}

}  // namespace

void AddDriverCheckOptions(CLI::App* app, CommonOptions* options) {
  CLI::Option* flag = app->add_flag(
      "--driver-check", options->driver_check,
      "also compile GLSL shaders with Mesa (OSMesa) and note where Mesa's verdict differs");
  app->add_option("--driver", options->driver, "Mesa driver for --driver-check (default softpipe)")
      ->check(CLI::IsMember({"softpipe", "llvmpipe"}))
      ->needs(flag);
}

Exit DriverCheck(const CommonOptions& options, glsl::Stage stage,
                 const std::vector<const compiler::SourceFile*>& sources,
                 compiler::FileReport* report) {
  runtime::MesaContext* mesa = GetMesa(options.driver);
  if (mesa == nullptr) return Exit::Environment;
  std::vector<std::string_view> strings;
  for (const compiler::SourceFile* source : sources) strings.push_back(source->text());
  // `arbiter check` links every shader (glsl::CheckOptions::link), so Mesa links it too.
  const runtime::MesaVerdict verdict = mesa->CompileGlsl(stage, strings, /*link=*/true);

  compiler::Diagnostic d;
  d.path = report->path;
  if (!verdict.failure.empty()) {
    d.info = &kRuntimeGlError;
    d.severity = compiler::Severity::Error;
    d.message = fmt::format("--driver-check: Mesa ({}) could not judge this shader: {}",
                            mesa->driver(), verdict.failure);
    report->diagnostics.push_back(std::move(d));
    return Exit::Environment;
  }
  const bool arbiter_accepts = ArbiterAccepts(*report);
  if (verdict.accepted == arbiter_accepts) return Exit::Ok;

  d.info = &kDriverCheckDiffers;
  d.severity = compiler::Severity::Note;
  if (verdict.accepted) {
    d.message = fmt::format("Mesa ({}) accepts this shader, arbiter rejects it", mesa->driver());
  } else {
    const std::string first = runtime::FirstErrorLine(verdict);
    d.message = fmt::format("Mesa ({}) rejects this shader{}, arbiter accepts it{}{}",
                            mesa->driver(), verdict.compiled ? " when linking it" : "",
                            first.empty() ? "" : "; Mesa says: ", first);
    LocateMesaMessage(first, sources, &d.file, &d.range);
  }
  report->diagnostics.push_back(std::move(d));
  return Exit::Ok;
}

}  // namespace arbiter::cli
