// mesa_load_arb: the comparison for `arbiter check` on ARB programs. Loads every file into
// one Mesa context (OSMesa, in process) with glProgramStringARB, as a driver validating the
// programs would, and prints how many Mesa accepted. Usage: mesa_load_arb [--driver
// softpipe|llvmpipe] FILE...  (bench/compare-arb.sh runs it beside arbiter.)
#include <fmt/format.h>

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/compiler/source.h"
#include "arbiter/runtime/mesa.h"

int main(int argc, char** argv) {
  arbiter::runtime::MesaOptions options;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    std::string_view arg = argv[i];
    if (arg == "--driver" && i + 1 < argc) {
      options.driver = argv[++i];
    } else {
      files.emplace_back(arg);
    }
  }
  std::string error;
  auto context = arbiter::runtime::CreateMesaContext(options, &error);
  if (!context) {
    fmt::print(stderr, "mesa_load_arb: {}\n", error);
    return 3;
  }
  size_t accepted = 0;
  for (const std::string& path : files) {
    std::string text;
    if (!arbiter::compiler::ReadFileBytes(path, &text, &error)) {
      fmt::print(stderr, "mesa_load_arb: {}: {}\n", path, error);
      return 3;
    }
    // The header names the target, as it does for arbiter.
    const auto kind = text.rfind("!!ARBfp", 0) == 0 ? arbiter::arbvp::ProgramKind::Fragment
                                                    : arbiter::arbvp::ProgramKind::Vertex;
    accepted += context->LoadArbProgram(kind, text).accepted ? 1 : 0;
  }
  fmt::print("{} of {} programs accepted by {}\n", accepted, files.size(), context->description());
  return 0;
}
