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
  std::string out = s.negate ? "-" : "";
  const Variable& v = ctx.program.vars[static_cast<size_t>(s.var)];
  if (s.relative) {
    std::string a = ctx.program.vars[static_cast<size_t>(s.address_var)].name + ".x";
    std::string off = s.index > 0   ? fmt::format(" + {}", s.index)
                      : s.index < 0 ? fmt::format(" - {}", -s.index)
                                    : "";
    out += fmt::format("{}[{}{}]", v.name, a, off);
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

}  // namespace

std::string InstructionComment(const Context& ctx, const Instruction& inst) {
  if (ctx.source != nullptr && inst.range.end > inst.range.begin &&
      inst.range.end <= ctx.source->text().size()) {
    std::string_view text(ctx.source->text());
    return Collapse(text.substr(inst.range.begin, inst.range.end - inst.range.begin)) + ";";
  }
  const OpcodeInfo& info = GetOpcodeInfo(inst.op);
  std::string out(info.name);
  if (inst.saturate) out += "_SAT";
  std::vector<std::string> operands;
  if (info.signature != OpSignature::Kil) {
    std::string dst = VarText(ctx, inst.dst.var, 0, false);
    if (inst.dst.mask != 0xF) {
      dst += ".";
      for (int c = 0; c < 4; ++c) {
        if (inst.dst.mask & (1u << c)) dst += "xyzw"[c];
      }
    }
    operands.push_back(dst);
  }
  for (int i = 0; i < inst.src_count; ++i) {
    operands.push_back(SrcText(ctx, inst, inst.src[static_cast<size_t>(i)]));
  }
  if (info.signature == OpSignature::Sample) {
    operands.push_back(fmt::format("texture[{}]", inst.tex_unit));
    operands.emplace_back(TexTargetName(inst.target));
  }
  for (size_t i = 0; i < operands.size(); ++i) out += (i ? ", " : " ") + operands[i];
  return out + ";";
}

}  // namespace arbiter::arbvp::emit
