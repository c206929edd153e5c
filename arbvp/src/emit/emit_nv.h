// The GLSL of the ALU instructions the NV program options add (opcodes.def rows with Nv /
// Nv2), one function each, as emit_instructions.cpp has them for the ARB instructions; the
// flow instructions are in emit_flow.h, TXD and TXL in emit_texture.h.
#pragma once

#include <string>

#include "emit/emit_context.h"

namespace arbiter::arbvp::emit {

std::string ARA(Context& ctx, const Instruction& inst);
std::string ARR(Context& ctx, const Instruction& inst);
// ARL of NV_vertex_program2: a vector floor into a four-component address register.
std::string ArlNv(Context& ctx, const Instruction& inst);
std::string DDX(Context& ctx, const Instruction& inst);
std::string DDY(Context& ctx, const Instruction& inst);
std::string DIV(Context& ctx, const Instruction& inst);
std::string DP2(Context& ctx, const Instruction& inst);
std::string DP2A(Context& ctx, const Instruction& inst);
std::string NRM(Context& ctx, const Instruction& inst);
std::string PK2H(Context& ctx, const Instruction& inst);
std::string PK2US(Context& ctx, const Instruction& inst);
std::string PK4B(Context& ctx, const Instruction& inst);
std::string PK4UB(Context& ctx, const Instruction& inst);
std::string RCC(Context& ctx, const Instruction& inst);
std::string RFL(Context& ctx, const Instruction& inst);
std::string SEQ(Context& ctx, const Instruction& inst);
std::string SFL(Context& ctx, const Instruction& inst);
std::string SGT(Context& ctx, const Instruction& inst);
std::string SLE(Context& ctx, const Instruction& inst);
std::string SNE(Context& ctx, const Instruction& inst);
std::string SSG(Context& ctx, const Instruction& inst);
std::string STR(Context& ctx, const Instruction& inst);
std::string UP2H(Context& ctx, const Instruction& inst);
std::string UP2US(Context& ctx, const Instruction& inst);
std::string UP4B(Context& ctx, const Instruction& inst);
std::string UP4UB(Context& ctx, const Instruction& inst);
std::string X2D(Context& ctx, const Instruction& inst);

// The write of an integer result (ARL, ARR, ARA, POPA) to an address register of an NV
// vertex program: `value(comps)` gives the ivecN of the written components.
std::string AssignAddress(Context& ctx, const Instruction& inst,
                          const std::function<std::string(const Comps&)>& value);

}  // namespace arbiter::arbvp::emit
