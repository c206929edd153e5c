// arbiter exec for GLSL shaders (a .vert, a .frag, or a pair) on Mesa: cli/cmd_exec.cpp
// sends GLSL inputs here. docs/exec.md, "GLSL shaders".
#pragma once

#include <string>
#include <vector>

#include "cli.h"
#include "options.h"

namespace arbiter::cli {

struct ExecGlslOptions {
  const CommonOptions* common = nullptr;
  std::string engine;  // as given ("" when not)
  const MesaOptions* mesa = nullptr;
  std::vector<std::string> set;
  std::vector<std::string> uniforms;
  std::vector<std::string> state;
  std::vector<std::string> textures;
  std::string vectors;
  bool pair = false;
};

// Whether exec's files are GLSL shaders (by --stage vert|frag or their names).
bool ExecFilesAreGlsl(const CommonOptions& options);

int RunExecGlsl(const ExecGlslOptions& options);

}  // namespace arbiter::cli
