// mesa_glsl_compile: Mesa's and arbiter's verdicts on GLSL shaders, one JSON line per file.
//
// Usage:
//   mesa_glsl_compile [--driver softpipe|llvmpipe] [--stats] FILE...
//
// Each file is judged as the GLSL corpus test judges it (docs/design/formats.md): the piglit `//
// [config]` block at the top decides; `check_link: true` compiles and links (arbiter:
// CheckOptions::link), anything else compiles only. Mesa compiles through an OSMesa context
// (arbiter::runtime); arbiter through glsl::CheckShader in this process. One line per file:
//   {"path":..., "stage":"vert"|"frag", "link":bool, "expect":"pass"|"fail"|null,
//    "mesa":{"accepted","compiled","linked","first_error","log","failure"},
//    "arbiter":{"accepted","diagnostics":["line:col: severity: message [code]", ...]}}
// A file whose `require_extensions` Mesa does not meet has "skip" (the reason) instead of the
// verdicts; a bad config block gives "config_error"; an unreadable file "io_error".
// --stats prints the context creation time and the time per file of each tool on stderr.
// The driver comes from --driver, else softpipe. Exit codes: 0 done (whatever the verdicts),
// 2 usage, 3 I/O or context error.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/source.h"
#include "arbiter/glsl/check.h"
#include "arbiter/glsl/test_config.h"
#include "arbiter/runtime/mesa.h"

namespace {

using Json = nlohmann::json;
using Clock = std::chrono::steady_clock;

// The first requirement of `require_extensions` the context does not meet, or "".
std::string UnmetRequirement(const std::string& list, const std::vector<std::string>& have) {
  std::istringstream words(list);
  for (std::string word; words >> word;) {
    const bool absent = word[0] == '!';
    const std::string name = absent ? word.substr(1) : word;
    const bool present = std::find(have.begin(), have.end(), name) != have.end();
    if (present == absent) return absent ? "Mesa has " + name : "Mesa lacks " + name;
  }
  return "";
}

double Milliseconds(Clock::time_point since) {
  return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

struct Totals {
  int files = 0;
  double mesa_ms = 0;
  double arbiter_ms = 0;
};

Json JudgeOne(arbiter::runtime::MesaContext& mesa, const std::string& path, Totals* totals) {
  Json out;
  out["path"] = path;
  std::string text;
  std::string error;
  if (!arbiter::compiler::ReadFileBytes(path, &text, &error)) {
    out["io_error"] = "cannot read: " + error;
    return out;
  }
  const std::optional<arbiter::glsl::Stage> stage = arbiter::glsl::StageFromPath(path);
  if (!stage) {
    out["io_error"] = "not a GLSL shader (.vert .vs .frag .fs)";
    return out;
  }
  out["stage"] = *stage == arbiter::glsl::Stage::Vertex ? "vert" : "frag";
  const arbiter::glsl::ParserTestConfig config = arbiter::glsl::ParseParserTestConfig(text);
  if (!config.error.empty()) {
    out["config_error"] = config.error;
    return out;
  }
  const auto value = [&config](const char* key) {
    auto it = config.values.find(key);
    return it == config.values.end() ? std::string() : it->second;
  };
  const bool link = value("check_link") == "true";
  out["link"] = link;
  out["expect"] = config.values.count("expect_result") != 0 ? Json(value("expect_result")) : Json();
  const std::string unmet = UnmetRequirement(value("require_extensions"), mesa.extensions());
  if (!unmet.empty()) {
    out["skip"] = unmet;
    return out;
  }

  Clock::time_point start = Clock::now();
  const arbiter::runtime::MesaVerdict verdict = mesa.CompileGlsl(*stage, {text}, link);
  totals->mesa_ms += Milliseconds(start);
  Json m;
  m["accepted"] = verdict.accepted;
  m["compiled"] = verdict.compiled;
  m["linked"] = verdict.linked;
  m["first_error"] = arbiter::runtime::FirstErrorLine(verdict);
  m["log"] = verdict.compile_log + verdict.link_log;
  if (!verdict.failure.empty()) m["failure"] = verdict.failure;
  out["mesa"] = std::move(m);

  start = Clock::now();
  arbiter::compiler::SourceFile source(path, text);
  arbiter::compiler::DiagnosticSink sink(0);
  arbiter::glsl::CheckOptions options;
  options.link = link;
  const arbiter::glsl::CheckResult result =
      arbiter::glsl::CheckShader(*stage, {&source}, options, &sink);
  totals->arbiter_ms += Milliseconds(start);
  Json diagnostics = Json::array();
  for (const arbiter::compiler::Diagnostic& d : sink.diagnostics()) {
    std::string where;
    if (d.file != nullptr) {
      const arbiter::compiler::LineCol lc = d.file->Locate(d.range.begin);
      where = std::to_string(lc.line) + ":" + std::to_string(lc.column) + ": ";
    }
    diagnostics.push_back(where + std::string(arbiter::compiler::SeverityName(d.severity)) + ": " +
                          d.message + " [" + std::string(d.info != nullptr ? d.info->code : "?") +
                          "]");
  }
  out["arbiter"] = {{"accepted", result.ok}, {"diagnostics", std::move(diagnostics)}};
  ++totals->files;
  return out;
}

int Usage(const char* message) {
  if (message != nullptr) std::fprintf(stderr, "mesa_glsl_compile: %s\n", message);
  std::fputs("usage: mesa_glsl_compile [--driver softpipe|llvmpipe] [--stats] FILE...\n", stderr);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  arbiter::runtime::MesaOptions options;
  bool stats = false;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--driver") {
      if (i + 1 >= argc) return Usage("--driver needs a value");
      options.driver = argv[++i];
    } else if (arg == "--stats") {
      stats = true;
    } else if (arg == "--help" || arg == "-h") {
      Usage(nullptr);
      return 0;
    } else if (arg == "--") {
      for (++i; i < argc; ++i) files.push_back(argv[i]);
    } else if (arg.rfind("--", 0) == 0) {
      return Usage(("unknown option " + arg).c_str());
    } else {
      files.push_back(arg);
    }
  }
  if (files.empty()) return Usage("no input files");
  if (!arbiter::runtime::IsSupportedMesaDriver(options.driver)) {
    return Usage(("unsupported driver '" + options.driver + "' (softpipe or llvmpipe)").c_str());
  }

  const Clock::time_point start = Clock::now();
  std::string error;
  std::unique_ptr<arbiter::runtime::MesaContext> mesa =
      arbiter::runtime::CreateMesaContext(options, &error);
  if (mesa == nullptr) {
    std::fprintf(stderr, "mesa_glsl_compile: %s\n", error.c_str());
    return 3;
  }
  const double create_ms = Milliseconds(start);

  int status = 0;
  Totals totals;
  for (const std::string& path : files) {
    Json line = JudgeOne(*mesa, path, &totals);
    if (line.contains("io_error")) status = 3;
    // Mesa's logs may hold any bytes: invalid UTF-8 becomes U+FFFD, the line stays JSON.
    std::string text = line.dump(-1, ' ', false, Json::error_handler_t::replace);
    text += '\n';
    std::fputs(text.c_str(), stdout);
    std::fflush(stdout);  // a crash on the next file must not lose this line
  }
  if (stats) {
    const double n = totals.files > 0 ? totals.files : 1;
    std::fprintf(stderr,
                 "mesa_glsl_compile: %s: context %.1f ms; %d shaders: Mesa %.3f ms/shader, "
                 "arbiter %.3f ms/shader\n",
                 mesa->description().c_str(), create_ms, totals.files, totals.mesa_ms / n,
                 totals.arbiter_ms / n);
  }
  return status;
}
