// Internal helpers of the state model shared by the interpreter.
#pragma once

#include <string>

#include "arbiter/arbvp/exec.h"

namespace arbiter::arbvp {

// Why the value of a state binding is undefined by the specs (the inverse of a singular
// matrix), or empty when it is defined.
std::string StateBindingUndefined(const GlState& state, const Binding& binding);

}  // namespace arbiter::arbvp
