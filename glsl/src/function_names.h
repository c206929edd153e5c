// GLSL 1.10's separate name space of functions (4.2), as glslang must be given it.
#pragma once

#include <string>
#include <vector>

#include "source_text.h"

namespace arbiter::glsl {

// GLSL 1.10 4.2: "Functions names are always identifiable as function names based on context,
// and they have their own name space." glslang 12 reads `foo(` as the constant `foo` where a
// const variable of that name is in scope. Each function of `texts` (one shader's strings and
// its preamble) that shares its name with a const variable is renamed wherever the name is
// followed by '(', to a name of the same length found nowhere in them; returns the renames.
// Each shader object is renamed alone: a function called, under such a const, in one object of
// a stage and defined in another does not link (a gap), nor is a built-in function renamed.
std::vector<Rename> SeparateFunctionNames(const std::vector<std::string*>& texts);

}  // namespace arbiter::glsl
