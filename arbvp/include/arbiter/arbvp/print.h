// Prints an IR program back as ARB assembly text that Mesa (or arbiter) loads: the runtime
// feeds Mesa rewritten programs (outputs redirected for readback) through this printer.
#pragma once

#include <string>

#include "arbiter/arbvp/ir.h"

namespace arbiter::arbvp {

// The program as ARB text: header, options, one declaration per variable in IR order
// (bindings used directly in instructions get a fresh name, so parsing the text again
// numbers the variables the same way), one line per instruction, END. Parsing the text again
// yields an equivalent program. Constants print with 9 significant digits, which round-trips
// every float; +-inf prints as +-1e39, which overflows back to +-inf when parsed (as in
// Mesa); NaN has no spelling in ARB and prints as 0.
std::string PrintProgram(const Program& program);

}  // namespace arbiter::arbvp
