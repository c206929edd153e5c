// The GLSL of the instructions the NV program options add (opcodes.def rows with Nv /
// Nv2), one function each, as emit_instructions.cpp has them for the ARB instructions.
#pragma once

#include <string>

#include "emit/emit_context.h"

namespace arbiter::arbvp::emit {

std::string ARA(Context& ctx, const Instruction& inst);
std::string ARR(Context& ctx, const Instruction& inst);
std::string BRA(Context& ctx, const Instruction& inst);
std::string BRK(Context& ctx, const Instruction& inst);
std::string CAL(Context& ctx, const Instruction& inst);
std::string DDX(Context& ctx, const Instruction& inst);
std::string DDY(Context& ctx, const Instruction& inst);
std::string DIV(Context& ctx, const Instruction& inst);
std::string DP2(Context& ctx, const Instruction& inst);
std::string DP2A(Context& ctx, const Instruction& inst);
std::string ELSE(Context& ctx, const Instruction& inst);
std::string ENDIF(Context& ctx, const Instruction& inst);
std::string ENDLOOP(Context& ctx, const Instruction& inst);
std::string ENDREP(Context& ctx, const Instruction& inst);
std::string IF(Context& ctx, const Instruction& inst);
std::string LOOP(Context& ctx, const Instruction& inst);
std::string NRM(Context& ctx, const Instruction& inst);
std::string PK2H(Context& ctx, const Instruction& inst);
std::string PK2US(Context& ctx, const Instruction& inst);
std::string PK4B(Context& ctx, const Instruction& inst);
std::string PK4UB(Context& ctx, const Instruction& inst);
std::string POPA(Context& ctx, const Instruction& inst);
std::string PUSHA(Context& ctx, const Instruction& inst);
std::string RCC(Context& ctx, const Instruction& inst);
std::string REP(Context& ctx, const Instruction& inst);
std::string RET(Context& ctx, const Instruction& inst);
std::string RFL(Context& ctx, const Instruction& inst);
std::string SEQ(Context& ctx, const Instruction& inst);
std::string SFL(Context& ctx, const Instruction& inst);
std::string SGT(Context& ctx, const Instruction& inst);
std::string SLE(Context& ctx, const Instruction& inst);
std::string SNE(Context& ctx, const Instruction& inst);
std::string SSG(Context& ctx, const Instruction& inst);
std::string STR(Context& ctx, const Instruction& inst);
std::string TXD(Context& ctx, const Instruction& inst);
std::string TXL(Context& ctx, const Instruction& inst);
std::string UP2H(Context& ctx, const Instruction& inst);
std::string UP2US(Context& ctx, const Instruction& inst);
std::string UP4B(Context& ctx, const Instruction& inst);
std::string UP4UB(Context& ctx, const Instruction& inst);
std::string X2D(Context& ctx, const Instruction& inst);

}  // namespace arbiter::arbvp::emit
