// The flow structure of an NV program: labels resolved to instruction indices, IF/ELSE/ENDIF,
// LOOP/ENDLOOP and REP/ENDREP matched, BRK tied to its loop (Instruction::jump).
#pragma once

#include <functional>
#include <string>

#include "arbiter/arbvp/ir.h"
#include "diag.h"

namespace arbiter::arbvp {

using FlowReport = std::function<compiler::Diagnostic*(Diag, Range, std::string)>;

// Sets every flow instruction's `jump`; reports undefined and repeated labels, unmatched
// block instructions and a BRK outside a loop.
void ResolveFlow(Program* program, const compiler::SourceFile& source, const FlowReport& report);

}  // namespace arbiter::arbvp
