// Operand rules that span statements: result.position under ARB_position_invariant,
// components the spec leaves undefined, temporaries read before written, a vertex program
// that never writes its position.
#include <fmt/format.h>

#include <vector>

#include "checks.h"

namespace arbiter::arbvp {
namespace {

bool IsPosition(const Binding& b) {
  return b.kind == BindingKind::Result && b.result == ResultReg::Position;
}

// Components of the source register an operand reads, given the written mask it feeds.
uint8_t ComponentsRead(const Instruction& inst, const SrcOperand& src) {
  const OpcodeInfo& info = GetOpcodeInfo(inst.op);
  uint8_t read = 0;
  auto add = [&](Swz s) {
    if (s <= Swz::W) read = static_cast<uint8_t>(read | (1u << static_cast<unsigned>(s)));
  };
  switch (info.signature) {
    case OpSignature::Scalar:
    case OpSignature::BinSc:
    case OpSignature::Arl:
      add(src.swizzle[0]);
      break;
    case OpSignature::Vector:
    case OpSignature::Binary:
    case OpSignature::Ternary:
    case OpSignature::Swz:
    case OpSignature::Sample:
    case OpSignature::Kil:
      for (Swz s : src.swizzle) add(s);
      break;
  }
  return read;
}

}  // namespace

void CheckOperands(const CheckContext& ctx) {
  const Program& program = ctx.program;
  if (program.HasOption(OptionId::PositionInvariant)) {
    for (const Variable& var : program.vars) {
      if (var.kind != VarKind::Output) continue;
      for (const Binding& b : var.bindings) {
        if (!IsPosition(b)) continue;
        ctx.Report(Diag::OperandPositionInvariant, b.range,
                   "a position-invariant program (OPTION ARB_position_invariant) cannot write "
                   "result.position: the GL computes it");
      }
    }
  }

  std::vector<uint8_t> written(program.vars.size(), 0);
  std::vector<bool> warned(program.vars.size(), false);
  bool position_written = false;
  for (const Instruction& inst : program.instructions) {
    for (size_t s = 0; s < inst.src_count; ++s) {
      const SrcOperand& src = inst.src[s];
      if (src.var < 0) continue;
      const Variable& var = program.vars[static_cast<size_t>(src.var)];
      if (var.kind != VarKind::Temp || warned[static_cast<size_t>(src.var)]) continue;
      uint8_t missing =
          static_cast<uint8_t>(ComponentsRead(inst, src) & ~written[static_cast<size_t>(src.var)]);
      if (missing) {
        warned[static_cast<size_t>(src.var)] = true;
        std::string comps;
        for (int c = 0; c < 4; ++c) {
          if (missing & (1u << c)) comps += "xyzw"[c];
        }
        ctx.Report(Diag::TempReadBeforeWrite, src.range,
                   fmt::format("temporary '{}' is read ('.{}') before any instruction writes "
                               "it; its value is undefined",
                               var.name, comps));
      }
    }
    const OpcodeInfo& info = GetOpcodeInfo(inst.op);
    if (info.signature == OpSignature::Kil || inst.dst.var < 0) continue;
    written[static_cast<size_t>(inst.dst.var)] |= inst.dst.mask;
    const Variable& dst = program.vars[static_cast<size_t>(inst.dst.var)];
    for (const Binding& b : dst.bindings) {
      if (IsPosition(b)) position_written = true;
    }
    if ((inst.op == Opcode::SCS && (inst.dst.mask & 0xC)) ||
        (inst.op == Opcode::XPD && (inst.dst.mask & 0x8))) {
      ctx.Report(
          Diag::UndefinedComponent, inst.dst.range,
          fmt::format("{} leaves the {} component{} of its result undefined; mask the "
                      "destination to '{}'",
                      info.name, inst.op == Opcode::SCS ? "z and w" : "w",
                      inst.op == Opcode::SCS ? "s" : "", inst.op == Opcode::SCS ? ".xy" : ".xyz"));
    }
  }
  if (ctx.vp() && !position_written && !program.HasOption(OptionId::PositionInvariant)) {
    ctx.Report(Diag::PositionNotWritten, program.end,
               "the vertex program never writes result.position; the vertex position is "
               "undefined (or use OPTION ARB_position_invariant)");
  }
}

}  // namespace arbiter::arbvp
