// The arbiter command: dispatches to one verb per subcommand.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/compiler/suggest.h"
#include "cli.h"
#include "driver_check.h"

namespace arbiter::cli {
// cmd_link.cpp: adds the `link` subcommand; the returned function runs it once parsed.
std::function<int()> AddLinkCommand(CLI::App* app);
// cmd_exec.cpp: adds the `exec` subcommand.
std::function<int()> AddExecCommand(CLI::App* app);
// cmd_translate.cpp: adds the `translate` subcommand.
std::function<int()> AddTranslateCommand(CLI::App* app);
// cmd_verify.cpp: adds the `verify` subcommand.
std::function<int()> AddVerifyCommand(CLI::App* app);
// cmd_run.cpp: adds the `run` subcommand.
std::function<int()> AddRunCommand(CLI::App* app);

// The first argument when it is no command: `help [COMMAND]` prints the help, anything else
// that is not an option is an unknown command, with the nearest one suggested. Returns the
// exit code then; nullopt lets the parser go on.
std::optional<int> HandleCommandWord(CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return std::nullopt;
  std::string_view word = argv[1];
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
  if (std::find(names.begin(), names.end(), word) != names.end()) return std::nullopt;
  if (word == "help") {
    if (argc == 2) {
      std::fputs(app.help().c_str(), stdout);
      return 0;
    }
    for (const CLI::App* sub : app.get_subcommands({})) {
      if (sub->get_name() == argv[2]) {
        std::fputs(sub->help("arbiter").c_str(), stdout);
        return 0;
      }
    }
    word = argv[2];  // help about a command that does not exist
  }
  const std::string nearest =
      compiler::ClosestMatch(word, std::vector<std::string_view>(names.begin(), names.end()));
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  std::string hint = nearest.empty() ? "" : fmt::format(" (did you mean '{}'?)", nearest);
  fmt::print(stderr, "arbiter: error: unknown command '{}'{}\ncommands: {} (arbiter --help)\n",
             word, hint, list);
  return static_cast<int>(Exit::Usage);
}

}  // namespace arbiter::cli

int main(int argc, char** argv) {
  using arbiter::cli::CommonOptions;
  using arbiter::cli::Exit;
  CLI::App app{"arbiter: check, translate and execute legacy OpenGL shader programs", "arbiter"};
  app.set_version_flag("-V,--version", ARBITER_VERSION);
  app.require_subcommand(1);
  app.footer("Run 'arbiter COMMAND --help' for a command's options.");

  CommonOptions check_options;
  CLI::App* check = app.add_subcommand(
      "check", "validate ARB vertex/fragment programs and GLSL 1.10/1.20 shaders");
  arbiter::cli::AddCommonOptions(check, &check_options, /*diagnostics=*/true);
  check->add_flag("--link", check_options.link,
                  "GLSL: judge the files as one program (glLinkProgram), not each as a shader "
                  "object (glCompileShader)");
  arbiter::cli::AddGlslOptions(check, &check_options);
  arbiter::cli::AddDriverCheckOptions(check, &check_options);

  CommonOptions info_options;
  CLI::App* info =
      app.add_subcommand("info", "statistics and reflection of ARB programs and GLSL shaders");
  arbiter::cli::AddCommonOptions(info, &info_options, /*diagnostics=*/false);
  arbiter::cli::AddGlslOptions(info, &info_options);

  std::function<int()> run_link = arbiter::cli::AddLinkCommand(&app);
  std::function<int()> run_translate = arbiter::cli::AddTranslateCommand(&app);
  std::function<int()> run_exec = arbiter::cli::AddExecCommand(&app);
  std::function<int()> run_verify = arbiter::cli::AddVerifyCommand(&app);
  std::function<int()> run_tests = arbiter::cli::AddRunCommand(&app);

  if (std::optional<int> code = arbiter::cli::HandleCommandWord(app, argc, argv)) return *code;
  try {
    // "-Werror" is the spelling compilers use; CLI11 would read it as -W followed by
    // "-error", so it is passed on as --Werror; -W<code>, -Wno-<code> and -Werror=<code>
    // likewise as --warning=<code>, --warning=no-<code>, --warning=error=<code>.
    std::vector<std::string> args;
    for (int i = argc - 1; i >= 1; --i) {
      std::string_view arg = argv[i];
      if (arg == "-Werror") {
        args.emplace_back("--Werror");
      } else if (arg.size() > 2 && arg.substr(0, 2) == "-W") {
        args.emplace_back("--warning=" + std::string(arg.substr(2)));
      } else {
        args.emplace_back(arg);
      }
    }
    app.parse(std::move(args));
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? 0 : static_cast<int>(Exit::Usage);
  }
  if (check->parsed()) return arbiter::cli::RunCheck(check_options);
  if (info->parsed()) return arbiter::cli::RunInfo(info_options);
  if (app.get_subcommand("link")->parsed()) return run_link();
  if (app.get_subcommand("translate")->parsed()) return run_translate();
  if (app.get_subcommand("exec")->parsed()) return run_exec();
  if (app.get_subcommand("verify")->parsed()) return run_verify();
  if (app.get_subcommand("run")->parsed()) return run_tests();
  return static_cast<int>(Exit::Usage);
}
