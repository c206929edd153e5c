// The texture instructions: TEX, TXB, TXP (ARBfp 3.11.6; vertex programs with
// NV_vertex_program3), TXL (NV_vertex_program3, NV_fragment_program2) and TXD
// (NV_fragment_program_option).
#pragma once

#include <string>

#include "emit/emit_context.h"

namespace arbiter::arbvp::emit {

std::string TEX(Context& ctx, const Instruction& inst);
std::string TXB(Context& ctx, const Instruction& inst);
std::string TXD(Context& ctx, const Instruction& inst);
std::string TXL(Context& ctx, const Instruction& inst);
std::string TXP(Context& ctx, const Instruction& inst);

}  // namespace arbiter::arbvp::emit
