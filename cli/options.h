// The options several commands take, each declared once here: one spelling, help text, check
// and default everywhere (--format, --color, --stage, --error-limit, -Werror, -j, and the Mesa
// engine's --backend, --driver, --timeout, --memory-limit).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace arbiter::cli {

// How a command runs Mesa (exec, verify, run).
struct MesaOptions {
  std::string backend = "osmesa";
  std::string driver = "softpipe";
  int timeout_ms = 10000;
  int memory_mib = 8192;
};

// --format with the formats a command writes (the first is the default).
void AddFormatOption(CLI::App* cmd, std::string* format, const std::vector<std::string>& formats);
void AddColorOption(CLI::App* cmd, std::string* color);
// --stage: the kind of an ARB program read from stdin; with `glsl`, vert and frag too.
void AddStageOption(CLI::App* cmd, std::string* stage, bool glsl);
void AddErrorLimitOption(CLI::App* cmd, int* error_limit);
// --limits: a built-in profile (compiler::BuiltinProfileNames) or a JSON file.
void AddLimitsOption(CLI::App* cmd, std::string* limits);
void AddWerrorFlag(CLI::App* cmd, bool* werror);
// -j: `unit` is what runs in parallel ("worker threads", "worker processes").
void AddJobsOption(CLI::App* cmd, int* jobs, std::string_view unit);
// --backend, --driver, --timeout (`timeout_what` says what the limit applies to),
// --memory-limit.
void AddMesaOptions(CLI::App* cmd, MesaOptions* mesa, std::string_view timeout_what);
// An option that takes one value and may be given again (--set a=1 --set b=2): its help shows
// one VALUE, not CLI11's "TEXT ...".
CLI::Option* AddRepeatedOption(CLI::App* cmd, const std::string& name,
                               std::vector<std::string>* values, const std::string& value_name,
                               const std::string& help);

}  // namespace arbiter::cli
