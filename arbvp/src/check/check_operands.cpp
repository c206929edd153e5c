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

// The operand components (before swizzling) that instruction `inst` reads from source
// `s`: the opcode table's `reads` column (ARBvp 2.14.5, ARBfp 3.11.5 and 3.11.6, the NV
// options' instruction sections).
uint8_t OperandComponentsUsed(const Instruction& inst, size_t s) {
  std::string_view reads = GetOpcodeInfo(inst.op).reads;
  for (size_t i = 0; i < s; ++i) {
    size_t comma = reads.find(',');
    if (comma == std::string_view::npos) break;
    reads.remove_prefix(comma + 1);
  }
  reads = reads.substr(0, reads.find(','));
  if (reads == "mask") return inst.dst.mask;  // component-wise: only the written ones
  uint8_t mask = 0;
  if (reads.starts_with("coord")) {
    mask = TexTargetCoordMask(inst.target);
    reads.remove_prefix(5);
  }
  for (char c : reads) {
    if (c >= 'x' && c <= 'z') mask = static_cast<uint8_t>(mask | (1u << (c - 'x')));
    if (c == 'w') mask = static_cast<uint8_t>(mask | 0x8u);
  }
  return mask;
}

// Components of the source register an operand reads.
uint8_t ComponentsRead(const Instruction& inst, size_t s) {
  const SrcOperand& src = inst.src[s];
  uint8_t used = OperandComponentsUsed(inst, s);
  uint8_t read = 0;
  for (size_t c = 0; c < 4; ++c) {
    if (!(used & (1u << c))) continue;
    Swz sel = src.swizzle[c];
    if (sel <= Swz::W) read = static_cast<uint8_t>(read | (1u << static_cast<unsigned>(sel)));
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

  // NV_fragment_program (RFL): "A fragment program will fail to load if the w component of
  // the result is enabled in the component write mask". NVIDIA's drivers load such programs
  // (piglit's size_specifier tests expect it), so arbiter warns and leaves w undefined.
  for (const Instruction& inst : program.instructions) {
    if (inst.op == Opcode::RFL && (inst.dst.mask & 0x8)) {
      ctx.Report(Diag::RflWritesW, inst.dst.range,
                 "RFL writes w, which is undefined; NV_fragment_program says such a program fails "
                 "to load (NVIDIA's drivers load it): mask the destination with .xyz");
    }
  }

  // After an error some statements are missing: data-flow warnings would only be echoes.
  if (ctx.sink->error_count() > ctx.errors_before) return;
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
          static_cast<uint8_t>(ComponentsRead(inst, s) & ~written[static_cast<size_t>(src.var)]);
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
