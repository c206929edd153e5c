// The ARB instruction a statement translates, as a one-line comment: its source text when
// the source is known, else a spelling rebuilt from the IR.
#include <fmt/format.h>

#include "emit/emit_context.h"

namespace arbiter::arbvp::emit {
namespace {

// Source text with ARB comments dropped and whitespace runs collapsed to one space.
std::string Collapse(std::string_view text) {
  std::string out;
  bool in_comment = false;
  bool space = false;
  for (char c : text) {
    if (c == '\n' || c == '\r') in_comment = false;
    if (c == '#') in_comment = true;
    if (in_comment) continue;
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      space = !out.empty();
      continue;
    }
    if (space) out += ' ';
    space = false;
    out += c;
  }
  return out;
}

std::string VarText(const Context& ctx, int var, int element, bool indexed) {
  const Variable& v = ctx.program.vars[static_cast<size_t>(var)];
  if (!v.name.empty()) return indexed ? fmt::format("{}[{}]", v.name, element) : v.name;
  if (v.bindings.empty()) return "?";
  return BindingName(v.bindings[static_cast<size_t>(indexed ? element : 0)], ctx.program.kind);
}

std::string SrcText(const Context& ctx, const Instruction& inst, const SrcOperand& s) {
  if (s.abs) {
    SrcOperand inner = s;
    inner.abs = false;
    inner.negate = false;
    return (s.negate ? "-|" : "|") + SrcText(ctx, inst, inner) + "|";
  }
  std::string out = s.negate ? "-" : "";
  const Variable& v = ctx.program.vars[static_cast<size_t>(s.var)];
  if (s.relative) {
    std::string a = (s.address_var >= 0 ? ctx.program.vars[static_cast<size_t>(s.address_var)].name
                                        : std::string("A0")) +
                    "." + "xyzw"[s.address_component & 3];
    std::string off = s.index > 0   ? fmt::format(" + {}", s.index)
                      : s.index < 0 ? fmt::format(" - {}", -s.index)
                                    : "";
    // An attribute array bound in the instruction: its binding without the element.
    std::string array = v.name;
    if (array.empty() && !v.bindings.empty()) {
      array = BindingName(v.bindings[0], ctx.program.kind);
      array = array.substr(0, array.find('['));
    }
    out += fmt::format("{}[{}{}]", array, a, off);
  } else {
    out += VarText(ctx, s.var, s.index, s.indexed);
  }
  std::string swz;
  bool identity = true;
  for (size_t i = 0; i < 4; ++i) {
    const char* names[] = {"x", "y", "z", "w", "0", "1"};
    if (inst.op == Opcode::SWZ) {
      swz += (i ? ", " : "") + std::string(s.component_negate[i] ? "-" : "") +
             names[static_cast<int>(s.swizzle[i])];
    } else {
      swz += names[static_cast<int>(s.swizzle[i])];
    }
    identity = identity && s.swizzle[i] == static_cast<Swz>(i);
  }
  if (inst.op == Opcode::SWZ) return out + ", " + swz;
  bool scalar = swz.find_first_not_of(swz[0]) == std::string::npos;
  if (scalar) return out + "." + swz[0];
  return identity ? out : out + "." + swz;
}

// A condition code test: "GT.x", "NE1", "TR".
std::string CcText(const CcTest& cc) {
  constexpr const char* kRules[] = {"EQ", "GE", "GT", "LE", "LT", "NE", "TR", "FL"};
  std::string out = kRules[static_cast<int>(cc.rule)];
  if (cc.reg != 0) out += std::to_string(cc.reg);
  std::string swz;
  for (Swz c : cc.swizzle) swz += "xyzw01"[static_cast<int>(c)];
  if (swz == "xyzw") return out;
  if (swz.find_first_not_of(swz[0]) == std::string::npos) return out + "." + swz[0];
  return out + "." + swz;
}

// Whether the instruction has a destination operand.
bool HasDst(const OpcodeInfo& info) {
  switch (info.signature) {
    case OpSignature::Kil:
    case OpSignature::PushA:
    case OpSignature::Branch:
    case OpSignature::FlowCc:
    case OpSignature::If:
    case OpSignature::Loop:
    case OpSignature::EndFlow:
      return false;
    case OpSignature::Vector:
    case OpSignature::Scalar:
    case OpSignature::BinSc:
    case OpSignature::Binary:
    case OpSignature::Ternary:
    case OpSignature::Swz:
    case OpSignature::Arl:
    case OpSignature::Sample:
    case OpSignature::VecSca:
    case OpSignature::Ara:
    case OpSignature::Arr:
    case OpSignature::PopA:
    case OpSignature::TexD:
      return true;
  }
  return true;
}

// The opcode with its suffixes: precision, condition code update, saturation.
std::string OpcodeText(const Instruction& inst) {
  std::string out(GetOpcodeInfo(inst.op).name);
  if (inst.precision != Precision::Default) out += "?RHX"[static_cast<int>(inst.precision)];
  if (inst.cc_update == 0) out += "C";
  if (inst.cc_update == 1) out += "C1";
  if (inst.saturate) out += "_SAT";
  if (inst.signed_saturate) out += "_SSAT";
  return out;
}

}  // namespace

std::string InstructionComment(const Context& ctx, const Instruction& inst) {
  if (ctx.source != nullptr && inst.range.end > inst.range.begin &&
      inst.range.end <= ctx.source->text().size()) {
    std::string_view text(ctx.source->text());
    return Collapse(text.substr(inst.range.begin, inst.range.end - inst.range.begin)) + ";";
  }
  const OpcodeInfo& info = GetOpcodeInfo(inst.op);
  std::string out = OpcodeText(inst);
  std::vector<std::string> operands;
  if (info.signature == OpSignature::Branch) out += " " + inst.label;
  if (info.signature == OpSignature::If || (inst.op == Opcode::KIL && inst.cond.present)) {
    operands.push_back(CcText(inst.cond));
  }
  if (HasDst(info)) {
    std::string dst = VarText(ctx, inst.dst.var, 0, false);
    if (inst.dst.mask != 0xF) {
      dst += ".";
      for (int c = 0; c < 4; ++c) {
        if (inst.dst.mask & (1u << c)) dst += "xyzw"[c];
      }
    }
    if (inst.dst.cc.present) dst += " (" + CcText(inst.dst.cc) + ")";
    operands.push_back(dst);
  }
  for (int i = 0; i < inst.src_count; ++i) {
    operands.push_back(SrcText(ctx, inst, inst.src[static_cast<size_t>(i)]));
  }
  if (info.signature == OpSignature::Sample || info.signature == OpSignature::TexD) {
    operands.push_back(fmt::format("texture[{}]", inst.tex_unit));
    operands.emplace_back(TexTargetName(inst.target));
  }
  for (size_t i = 0; i < operands.size(); ++i) out += (i ? ", " : " ") + operands[i];
  // <optBranchCond> of BRA, CAL, RET, BRK.
  const bool branch =
      info.signature == OpSignature::Branch || info.signature == OpSignature::FlowCc;
  if (branch && inst.cond.present) out += " (" + CcText(inst.cond) + ")";
  return out + ";";
}

}  // namespace arbiter::arbvp::emit
