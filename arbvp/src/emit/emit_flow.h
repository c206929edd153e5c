// The GLSL of the NV flow instructions (BRA, CAL, RET, BRK, IF, ELSE, ENDIF, LOOP, ENDLOOP,
// REP, ENDREP) and of the address stack (PUSHA, POPA): statements of a structured body or
// steps of the program-counter machine, as EmitBody lays the program out (ctx.flow).
#pragma once

#include <string>

#include "emit/emit_context.h"

namespace arbiter::arbvp::emit {

std::string BRA(Context& ctx, const Instruction& inst);
std::string BRK(Context& ctx, const Instruction& inst);
std::string CAL(Context& ctx, const Instruction& inst);
std::string ELSE(Context& ctx, const Instruction& inst);
std::string ENDIF(Context& ctx, const Instruction& inst);
std::string ENDLOOP(Context& ctx, const Instruction& inst);
std::string ENDREP(Context& ctx, const Instruction& inst);
std::string IF(Context& ctx, const Instruction& inst);
std::string LOOP(Context& ctx, const Instruction& inst);
std::string POPA(Context& ctx, const Instruction& inst);
std::string PUSHA(Context& ctx, const Instruction& inst);
std::string REP(Context& ctx, const Instruction& inst);
std::string RET(Context& ctx, const Instruction& inst);

}  // namespace arbiter::arbvp::emit
