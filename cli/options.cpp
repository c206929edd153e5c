#include "options.h"

#include <fmt/format.h>

#include "arbiter/compiler/limits.h"

namespace arbiter::cli {

namespace {
// Bounds of the numeric options: wide enough for any real use, and printable in an error
// (CLI::NonNegativeNumber says "0 to 1.79769e+308").
constexpr int kMaxCount = 1000000;
}  // namespace

void AddFormatOption(CLI::App* cmd, std::string* format, const std::vector<std::string>& formats) {
  *format = formats.front();
  cmd->add_option("--format", *format, "output format")
      ->check(CLI::IsMember(formats))
      ->capture_default_str();
}

void AddColorOption(CLI::App* cmd, std::string* color) {
  cmd->add_option("--color", *color, "colour text output: auto (on a terminal), always, never")
      ->check(CLI::IsMember({"auto", "always", "never"}))
      ->capture_default_str();
}

void AddStageOption(CLI::App* cmd, std::string* stage, bool glsl) {
  if (glsl) {
    cmd->add_option("--stage", *stage,
                    "program kind instead of the header's (arbvp, arbfp) or the file name's "
                    "(vert, frag)")
        ->check(CLI::IsMember({"arbvp", "arbfp", "vert", "frag"}));
  } else {
    cmd->add_option("--stage", *stage, "the kind of an ARB program read from stdin")
        ->check(CLI::IsMember({"arbvp", "arbfp"}));
  }
}

void AddErrorLimitOption(CLI::App* cmd, int* error_limit) {
  cmd->add_option("--error-limit", *error_limit,
                  "stop reporting errors of a file after N (0: no limit)")
      ->check(CLI::Range(0, kMaxCount))
      ->capture_default_str();
}

void AddLimitsOption(CLI::App* cmd, std::string* limits) {
  std::string names;
  for (std::string_view name : compiler::BuiltinProfileNames()) {
    names += fmt::format("{}, ", name);
  }
  cmd->add_option("--limits", *limits,
                  fmt::format("limit profile: {}or a JSON file (default: mesa, without warnings "
                              "past the spec minimums)",
                              names));
}

void AddWerrorFlag(CLI::App* cmd, bool* werror) {
  cmd->add_flag("-W,--Werror", *werror, "treat warnings as errors");
}

void AddJobsOption(CLI::App* cmd, int* jobs, std::string_view unit) {
  cmd->add_option("-j,--jobs", *jobs, fmt::format("{} (default: one per core)", unit))
      ->check(CLI::Range(0, 256));
}

void AddMesaOptions(CLI::App* cmd, MesaOptions* mesa, std::string_view timeout_what) {
  cmd->add_option("--backend", mesa->backend, "Mesa through osmesa or egl (surfaceless)")
      ->check(CLI::IsMember({"osmesa", "egl"}))
      ->capture_default_str();
  cmd->add_option("--driver", mesa->driver, "Mesa's driver")
      ->check(CLI::IsMember({"softpipe", "llvmpipe"}))
      ->capture_default_str();
  cmd->add_option("--timeout", mesa->timeout_ms, fmt::format("time limit {}, ms", timeout_what))
      ->check(CLI::Range(100, 3600000))
      ->capture_default_str();
  cmd->add_option("--memory-limit", mesa->memory_mib, "memory limit of a Mesa worker, MiB")
      ->check(CLI::Range(256, 1 << 20))
      ->capture_default_str();
}

CLI::Option* AddRepeatedOption(CLI::App* cmd, const std::string& name,
                               std::vector<std::string>* values, const std::string& value_name,
                               const std::string& help) {
  return cmd->add_option(name, *values, help)
      ->type_name(value_name)
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->allow_extra_args(false);
}

}  // namespace arbiter::cli
