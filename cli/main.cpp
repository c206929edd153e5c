// The arbiter command: dispatches to one verb per subcommand.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "cli.h"

int main(int argc, char** argv) {
  using arbiter::cli::CommonOptions;
  using arbiter::cli::Exit;
  CLI::App app{"arbiter: check, translate and execute legacy OpenGL shader programs"};
  app.set_version_flag("--version", ARBITER_VERSION);
  app.require_subcommand(1);

  CommonOptions check_options;
  CLI::App* check = app.add_subcommand("check", "validate ARB vertex/fragment programs");
  arbiter::cli::AddCommonOptions(check, &check_options, /*diagnostics=*/true);

  CommonOptions info_options;
  CLI::App* info = app.add_subcommand("info", "statistics and reflection of ARB programs");
  arbiter::cli::AddCommonOptions(info, &info_options, /*diagnostics=*/false);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? 0 : static_cast<int>(Exit::Usage);
  }
  if (check->parsed()) return arbiter::cli::RunCheck(check_options);
  if (info->parsed()) return arbiter::cli::RunInfo(info_options);
  return static_cast<int>(Exit::Usage);
}
