// Reading and checking the ARB programs a command runs or translates (exec, translate,
// verify): diagnostics go to stderr as text, so that stdout holds the command's output.
#pragma once

#include <memory>
#include <vector>

#include "arbiter/arbvp/check.h"
#include "cli.h"

namespace arbiter::cli {

struct LoadedArb {
  Input input;
  std::unique_ptr<compiler::SourceFile> source;
  arbvp::CheckResult checked;
  bool ok() const { return source && checked.ok && checked.program; }
};

// Reads and checks every file of options.files (--stage, --limits, -Werror, --error-limit
// apply); prints the diagnostics. Returns the worst outcome: Rejected when a program has
// errors, Environment when a file cannot be read (it is then not in `loaded`).
Exit LoadArbPrograms(const CommonOptions& options, std::vector<LoadedArb>* loaded);

}  // namespace arbiter::cli
