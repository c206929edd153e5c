// The semantics of every ARB opcode: one float32 function per row of opcodes.def.
#pragma once

#include "arbiter/arbvp/ir.h"
#include "exec/machine.h"

namespace arbiter::arbvp::exec {

// Computes the result vector of `op` from ctx.src, before _SAT and the write mask. ARL
// returns floor(operand) in x (the caller loads the address register); KIL returns nothing
// and sets ctx.killed / ctx.kill_why.
Reg Execute(Opcode op, OpContext& ctx);

}  // namespace arbiter::arbvp::exec
