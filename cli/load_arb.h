// Reading and checking the ARB programs a command runs or translates (exec, translate,
// verify). The diagnostics are returned, not printed: each command prints them as text on
// stderr (stdout holds its output) or puts them in its JSON document.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "arbiter/arbvp/check.h"
#include "cli.h"

namespace arbiter::cli {

struct LoadedArb {
  Input input;
  std::unique_ptr<compiler::SourceFile> source;
  arbvp::CheckResult checked;
  bool rejected = false;  // an error, a warning under -Werror among them
  bool ok() const { return source && checked.ok && checked.program && !rejected; }
};

// Reads and checks every file of options.files (--stage, --limits, -Werror, --error-limit
// apply). `loaded` gets every program read, rejected ones too (ok() is false); `reports` the
// diagnostics of every input that has any, in input order. `command` names the verb for the
// note a GLSL shader gets ("translate takes ARB programs"). Returns the worst outcome: Usage
// for a bad --stage or --limits, Rejected when a program has errors, Environment when a file
// cannot be read (it is then not in `loaded`).
Exit LoadArbPrograms(const CommonOptions& options, std::string_view command,
                     std::vector<LoadedArb>* loaded, std::vector<compiler::FileReport>* reports);

// Prints LoadArbPrograms' reports as text on stderr (whatever --format says).
void PrintLoadReports(const std::vector<compiler::FileReport>& reports,
                      const CommonOptions& options);

}  // namespace arbiter::cli
