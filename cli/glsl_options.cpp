// The GLSL options of check, info and link: -D, -U, -I, --preamble, and the warning switches.
#include <fmt/format.h>

#include <set>

#include "arbiter/arbvp/check.h"
#include "arbiter/glsl/check.h"
#include "arbiter/glsl/link.h"
#include "cli.h"
#include "options.h"

namespace arbiter::cli {
namespace {

// Every diagnostic code arbiter has (ARB and GLSL), for the warning switches.
const std::set<std::string_view>& KnownCodes() {
  static const std::set<std::string_view> codes = [] {
    std::set<std::string_view> all;
    for (const compiler::DiagnosticInfo* info : arbvp::AllDiagnostics()) all.insert(info->code);
    for (const compiler::DiagnosticInfo* info : glsl::AllDiagnostics()) all.insert(info->code);
    return all;
  }();
  return codes;
}

// -W<code> (the warning stays on), -Wno-<code> (off), -Werror=<code> (an error).
bool ParseWarningSwitch(const std::string& value, compiler::WarningPolicy* policy) {
  std::string_view code = value;
  compiler::WarningAction action = compiler::WarningAction::Default;
  if (code.substr(0, 3) == "no-") {
    code.remove_prefix(3);
    action = compiler::WarningAction::Off;
  } else if (code.substr(0, 6) == "error=") {
    code.remove_prefix(6);
    action = compiler::WarningAction::Error;
  }
  if (KnownCodes().count(code) == 0) {
    fmt::print(stderr,
               "arbiter: error: -W{}: unknown diagnostic code '{}' (docs/diagnostics.md lists "
               "them)\n",
               value, code);
    return false;
  }
  policy->codes[std::string(code)] = action;
  return true;
}

}  // namespace

void AddGlslOptions(CLI::App* app, CommonOptions* options) {
  AddRepeatedOption(app, "-D,--define", &options->defines, "NAME[=VALUE]",
                    "GLSL: define a macro before the shader; repeatable");
  AddRepeatedOption(app, "-U,--undefine", &options->undefines, "NAME",
                    "GLSL: undefine a macro -D defined; repeatable");
  AddRepeatedOption(app, "-I,--include-dir", &options->include_dirs, "DIR",
                    "GLSL: where #include looks (GL_ARB_shading_language_include); repeatable");
  app->add_option("--preamble", options->preamble,
                  "GLSL: a file of text the application puts after #version");
  AddRepeatedOption(app, "--warning", &options->warnings, "CODE",
                    "-W<code>, -Wno-<code>, -Werror=<code>: switch one warning");
}

std::optional<Exit> ResolveGlslSetup(const CommonOptions& options, GlslSetup* out) {
  if (!ResolveLimits(options, &out->profile)) return Exit::Usage;
  out->check.profile = out->profile ? &*out->profile : nullptr;
  out->check.link = false;
  for (const std::string& d : options.defines) {
    if (d.empty() || !(std::isalpha(static_cast<unsigned char>(d[0])) || d[0] == '_')) {
      fmt::print(stderr, "arbiter: error: -D {}: a macro name must start with a letter or '_'\n",
                 d);
      return Exit::Usage;
    }
    out->check.preprocessor.defines.push_back(d);
  }
  for (const std::string& u : options.undefines) out->check.preprocessor.defines.push_back("-" + u);
  out->check.preprocessor.include_dirs = options.include_dirs;
  if (!options.preamble.empty()) {
    std::string bytes;
    std::string error;
    if (!compiler::ReadFileBytes(options.preamble, &bytes, &error)) {
      fmt::print(stderr, "arbiter: error: --preamble {}: {}\n", options.preamble, error);
      return Exit::Environment;
    }
    out->preamble = std::make_unique<compiler::SourceFile>(options.preamble, std::move(bytes));
    out->check.preprocessor.preamble = out->preamble.get();
  }
  out->warnings.werror = options.werror;
  for (const std::string& w : options.warnings) {
    if (!ParseWarningSwitch(w, &out->warnings)) return Exit::Usage;
  }
  return std::nullopt;
}

Exit LinkAndReport(const std::vector<glsl::ShaderObject>& objects, const CommonOptions& options,
                   const GlslSetup& glsl_setup,
                   const std::vector<std::unique_ptr<compiler::SourceFile>>& keep,
                   std::vector<compiler::FileReport>* reports) {
  compiler::DiagnosticSink sink(options.error_limit);
  glsl::LinkOptions link;
  link.profile = glsl_setup.check.profile;
  link.check = glsl_setup.check;
  glsl::LinkShaders(objects, link, &sink);
  sink.ApplyWarningPolicy(glsl_setup.warnings);
  const Exit exit = sink.error_count() + sink.dropped() > 0 ? Exit::Rejected : Exit::Ok;
  DistributeDiagnostics(&sink, keep, reports);
  return exit;
}

}  // namespace arbiter::cli
