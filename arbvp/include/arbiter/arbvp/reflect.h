// Reflection of a checked ARB program: what it reads, what it writes, what it uses.
#pragma once

#include <string>
#include <vector>

#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/ir.h"

namespace arbiter::arbvp {

struct ReflectedVariable {
  std::string name;                   // "" for a binding used inline
  std::vector<std::string> bindings;  // canonical spellings, one per vector
};

struct TextureUse {
  int unit = 0;
  std::string target;  // "2D", "SHADOW2D", ...
};

struct Reflection {
  std::string kind;  // "vertex" or "fragment"
  std::vector<std::string> options;
  Stats stats;
  std::vector<ReflectedVariable> attributes;
  std::vector<ReflectedVariable> parameters;
  std::vector<int> env_indices;              // program.env[n] referenced, sorted, unique
  std::vector<int> local_indices;            // program.local[n] referenced, sorted, unique
  std::vector<std::string> state;            // state bindings referenced, sorted, unique
  std::vector<std::string> outputs_written;  // result bindings some instruction writes
  std::vector<TextureUse> textures;          // per unit, sorted by unit
};

// Builds the reflection of a program the checker accepted.
Reflection Reflect(const Program& program, const Stats& stats);

}  // namespace arbiter::arbvp
