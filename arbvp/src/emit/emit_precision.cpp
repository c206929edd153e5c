// NV_fragment_program precision (3.11.4.2): the R, H and X suffixes and SHORT storage as
// conversions of operands and results, written out by arb_fp16 and arb_fx12 (emit_helpers).
#include <fmt/format.h>

#include "emit/emit_context.h"

namespace arbiter::arbvp::emit {
namespace {

// Whether an ALU opcode has the H suffix (NV_fragment_program2's table X.5, which has them
// all): those without run at fp32 (packing, texture, flow).
bool HasHalf(Opcode op) {
  const OpcodeInfo& info = GetOpcodeInfo(op);
  return info.klass == OpClass::Alu && info.fp2_mods.find('H') != std::string_view::npos;
}

bool IsShort(const Context& ctx, int var) {
  return var >= 0 && ctx.program.vars[static_cast<size_t>(var)].size == VarSize::Short;
}

}  // namespace

// "If no precision suffix is specified, calculations are carried out using the precision of
// the temporary register receiving the result": H for a SHORT one, where the opcode has H.
Conversion InstructionConversion(const Context& ctx, const Instruction& inst) {
  if (ctx.IsVertex() || !ctx.program.Nv()) return Conversion::None;
  switch (inst.precision) {
    case Precision::R:
      return Conversion::None;
    case Precision::H:
      return Conversion::Fp16;
    case Precision::X:
      return Conversion::Fx12;
    case Precision::Default:
      break;
  }
  if (HasHalf(inst.op) && IsShort(ctx, inst.dst.var)) return Conversion::Fp16;
  return Conversion::None;
}

// Whether `e` is a call of `function` as a whole ("arb_fp16(a) * arb_fp16(b)" is not).
bool IsCallOf(const Expr& e, std::string_view function) {
  if (e.text.rfind(function, 0) != 0 || e.text.size() <= function.size() ||
      e.text[function.size()] != '(') {
    return false;
  }
  int depth = 0;
  for (size_t i = function.size(); i < e.text.size(); ++i) {
    if (e.text[i] == '(') ++depth;
    if (e.text[i] == ')' && --depth == 0) return i + 1 == e.text.size();
  }
  return false;
}

// A converted value converts to itself (MOVH of an fp16 operand): no second call.
Expr Convert(Context& ctx, const Expr& e, Conversion conversion) {
  if (IsCallOf(e, "arb_fp16") && conversion == Conversion::Fp16) return e;
  if (IsCallOf(e, "arb_fx12") && conversion == Conversion::Fx12) return e;
  switch (conversion) {
    case Conversion::None:
      return e;
    case Conversion::Fp16:
      if (ctx.Mutated(Mutation::Fp16RoundingDropped)) return e;
      ctx.helpers.insert(Helper::Fp16);
      return {fmt::format("arb_fp16({})", e.text), e.width, true};
    case Conversion::Fx12:
      ctx.helpers.insert(Helper::RoundEven);
      ctx.helpers.insert(Helper::Fx12);
      return {fmt::format("arb_fx12({})", e.text), e.width, true};
  }
  return e;
}

// fp16 and fx12 values (and their [0, 1] or [-1, 1] clamps) are fp16 values already: only
// an fp32 result needs converting for a SHORT register.
Conversion StorageConversion(const Context& ctx, int var, Conversion done) {
  if (ctx.IsVertex() || !IsShort(ctx, var) || done != Conversion::None) return Conversion::None;
  return Conversion::Fp16;
}

}  // namespace arbiter::arbvp::emit
