// PrintProgram: the IR back as ARB assembly text (the runtime loads rewritten programs into
// Mesa through it).
#include "arbiter/arbvp/print.h"

#include <fmt/format.h>

#include <cmath>
#include <set>

#include "nv_syntax.h"

namespace arbiter::arbvp {
namespace {

// A float that parses back to the same value. inf has no spelling in ARB, but a literal
// beyond the float range overflows to it when parsed (strtof, as Mesa's lexer does), so +-inf
// prints as +-1e39. NaN has no spelling at all and prints as 0 (no parsed program holds one:
// only IR built by hand can).
std::string FloatText(float v) {
  if (std::isnan(v)) return "0";
  if (std::isinf(v)) return v > 0 ? "1e39" : "-1e39";
  return fmt::format("{:.9g}", v);
}

std::string BindingText(const Binding& b, ProgramKind kind) {
  if (b.kind == BindingKind::Constant) {
    return fmt::format("{{{}, {}, {}, {}}}", FloatText(b.value[0]), FloatText(b.value[1]),
                       FloatText(b.value[2]), FloatText(b.value[3]));
  }
  return BindingName(b, kind);
}

// Names every variable: declared names stay, implicit bindings (used directly in an
// instruction) get a fresh name that no declared one takes.
std::vector<std::string> VariableNames(const Program& program) {
  std::set<std::string> taken;
  for (const Variable& var : program.vars) {
    if (!var.name.empty()) taken.insert(var.name);
  }
  std::vector<std::string> names;
  names.reserve(program.vars.size());
  for (size_t i = 0; i < program.vars.size(); ++i) {
    const Variable& var = program.vars[i];
    if (!var.name.empty()) {
      names.push_back(var.name);
      continue;
    }
    std::string name = fmt::format("arbiter_v{}", i);
    while (taken.count(name) != 0) name += "_";
    taken.insert(name);
    names.push_back(name);
  }
  return names;
}

std::string Declaration(const Variable& var, const std::string& name, ProgramKind kind) {
  if (var.size != VarSize::Default && (var.kind == VarKind::Temp || var.kind == VarKind::Output)) {
    Variable plain = var;
    plain.size = VarSize::Default;
    return (var.size == VarSize::Short ? "SHORT " : "LONG ") + Declaration(plain, name, kind);
  }
  switch (var.kind) {
    case VarKind::Temp:
      return fmt::format("TEMP {};", name);
    case VarKind::Address:
      return fmt::format("ADDRESS {};", name);
    case VarKind::Attrib:
      return fmt::format("ATTRIB {} = {};", name, BindingText(var.bindings.at(0), kind));
    case VarKind::Output:
      return fmt::format("OUTPUT {} = {};", name, BindingText(var.bindings.at(0), kind));
    case VarKind::Param:
      if (!var.is_array) {
        return fmt::format("PARAM {} = {};", name, BindingText(var.bindings.at(0), kind));
      } else {
        std::string text = fmt::format("PARAM {}[{}] = {{", name, var.bindings.size());
        for (size_t i = 0; i < var.bindings.size(); ++i) {
          text += fmt::format("{}\n  {}", i == 0 ? "" : ",", BindingText(var.bindings[i], kind));
        }
        return text + " };";
      }
  }
  return "";
}

char ComponentChar(Swz s) {
  switch (s) {
    case Swz::X:
      return 'x';
    case Swz::Y:
      return 'y';
    case Swz::Z:
      return 'z';
    case Swz::W:
      return 'w';
    case Swz::Zero:
      return '0';
    case Swz::One:
      return '1';
  }
  return 'x';
}

std::string MaskText(uint8_t mask) {
  std::string text = ".";
  for (int i = 0; i < 4; ++i) {
    if ((mask >> i) & 1) text += "xyzw"[i];
  }
  return text;
}

class Printer {
 public:
  explicit Printer(const Program& program) : program_(program), names_(VariableNames(program)) {}

  std::string Print() {
    std::string out = program_.kind == ProgramKind::Vertex ? "!!ARBvp1.0\n" : "!!ARBfp1.0\n";
    for (const Option& option : program_.options) {
      out += fmt::format("OPTION {};\n", GetOptionInfo(option.id).spelling);
    }
    // Every variable in IR order, so that parsing the text again numbers them the same way.
    for (size_t i = 0; i < program_.vars.size(); ++i) {
      if (Undeclared(program_.vars[i])) continue;
      out += Declaration(program_.vars[i], names_[i], program_.kind) + "\n";
    }
    for (size_t i = 0; i <= program_.instructions.size(); ++i) {
      for (const Label& label : program_.labels) {
        if (label.index == static_cast<int>(i)) out += label.name + ":\n";
      }
      if (i < program_.instructions.size()) {
        out += PrintInstruction(program_.instructions[i]) + "\n";
      }
    }
    return out + "END\n";
  }

 private:
  std::string PrintInstruction(const Instruction& inst) {
    const OpcodeInfo& info = GetOpcodeInfo(inst.op);
    std::string text(info.name);
    if (inst.precision != Precision::Default) text += "?RHX"[static_cast<int>(inst.precision)];
    if (inst.cc_update == 0) text += "C";
    if (inst.cc_update == 1) text += "C1";
    if (inst.saturate) text += "_SAT";
    if (inst.signed_saturate) text += "_SSAT";
    switch (info.signature) {
      case OpSignature::Branch:
        return fmt::format("{} {}{};", text, inst.label, CcMask(inst.cond));
      case OpSignature::FlowCc:
      case OpSignature::EndFlow:
        return fmt::format("{}{};", text, CcMask(inst.cond));
      case OpSignature::If:
        return fmt::format("{} {};", text, CcTestText(inst.cond));
      case OpSignature::Kil:
        if (inst.cond.present) return fmt::format("{} {};", text, CcTestText(inst.cond));
        break;
      case OpSignature::PushA:
        return fmt::format("{} {};", text, names_.at(static_cast<size_t>(inst.src[0].var)));
      default:
        break;
    }
    std::vector<std::string> operands;
    const bool has_dst = info.signature != OpSignature::Kil && info.signature != OpSignature::Loop;
    if (has_dst) operands.push_back(Dst(inst.dst));
    if (info.signature == OpSignature::Swz) {
      operands.push_back(ExtendedSwizzle(inst.src[0]));
    } else if (info.signature == OpSignature::Ara) {
      operands.push_back(names_.at(static_cast<size_t>(inst.src[0].var)));
    } else {
      for (int i = 0; i < inst.src_count; ++i) operands.push_back(Src(inst.src[i]));
    }
    if (info.signature == OpSignature::Sample || info.signature == OpSignature::TexD) {
      operands.push_back(fmt::format("texture[{}]", inst.tex_unit));
      operands.emplace_back(TexTargetName(inst.target));
    }
    for (size_t i = 0; i < operands.size(); ++i) text += (i == 0 ? " " : ", ") + operands[i];
    return text + ";";
  }

  // Relatively addressed attribute and result arrays, and NV_fragment_program2's A0, have no
  // declaration: the program spells them where it uses them.
  bool Undeclared(const Variable& var) const {
    return var.relative_array ||
           (program_.kind == ProgramKind::Fragment && var.kind == VarKind::Address);
  }

  // "vertex.attrib[A0.x + 2]": the array's spelling and a relative index.
  std::string RelativeText(int var, int address_var, uint8_t component, int index) {
    const Variable& v = program_.vars.at(static_cast<size_t>(var));
    std::string text = v.relative_array ? BindingName(v.bindings.at(0), program_.kind)
                                        : names_.at(static_cast<size_t>(var));
    if (v.relative_array && text.find('[') != std::string::npos) text.resize(text.rfind('['));
    std::string address =
        fmt::format("{}.{}", names_.at(static_cast<size_t>(address_var)), "xyzw"[component & 3]);
    if (index > 0) return fmt::format("{}[{} + {}]", text, address, index);
    if (index < 0) return fmt::format("{}[{} - {}]", text, address, -index);
    return fmt::format("{}[{}]", text, address);
  }

  std::string Dst(const DstOperand& dst) {
    std::string text =
        dst.relative ? RelativeText(dst.var, dst.address_var, dst.address_component, dst.index)
                     : names_.at(static_cast<size_t>(dst.var));
    // An ARB address register always spells its only component (<addrWriteMask> is
    // required); NV address registers are vectors.
    bool address = program_.vars.at(static_cast<size_t>(dst.var)).kind == VarKind::Address;
    if (dst.mask != 0xF || (address && !program_.Nv())) text += MaskText(dst.mask);
    return text + CcMask(dst.cc);
  }

  // <ccTest> and <ccMask> of the NV options ("GT1.xyzw", " (GT1.xyzw)").
  static std::string CcTestText(const CcTest& cc) {
    std::string text(CcRuleName(cc.rule));
    if (cc.reg == 1) text += "1";
    text += ".";
    for (Swz c : cc.swizzle) text += ComponentChar(c);
    return text;
  }
  static std::string CcMask(const CcTest& cc) {
    return cc.present ? " (" + CcTestText(cc) + ")" : "";
  }

  std::string Register(const SrcOperand& src) {
    std::string text = names_.at(static_cast<size_t>(src.var));
    if (src.relative) {
      return RelativeText(src.var, src.address_var, src.address_component, src.index);
    }
    if (src.indexed) text += fmt::format("[{}]", src.index);
    return text;
  }

  std::string Src(const SrcOperand& src) {
    std::string text = src.abs ? "|" + Register(src) : Register(src);
    if (src.negate) text = "-" + text;
    const auto& s = src.swizzle;
    if (s[0] == s[1] && s[1] == s[2] && s[2] == s[3]) {
      // A replicated component: the scalar form, which scalar instructions require.
      text += ".";
      text += ComponentChar(s[0]);
    } else if (!(s[0] == Swz::X && s[1] == Swz::Y && s[2] == Swz::Z && s[3] == Swz::W)) {
      text += ".";
      for (Swz c : s) text += ComponentChar(c);
    }
    return src.abs ? text + "|" : text;
  }

  // <extendedSwizzle>: the register (SWZ allows no sign there, so a negated source flips
  // every component's sign), then four comma-separated components with signs.
  std::string ExtendedSwizzle(const SrcOperand& src) {
    std::string text = Register(src);
    for (size_t i = 0; i < 4; ++i) {
      text += ", ";
      if (src.component_negate[i] != src.negate) text += "-";
      text += ComponentChar(src.swizzle[i]);
    }
    return text;
  }

  const Program& program_;
  std::vector<std::string> names_;
};

}  // namespace

std::string PrintProgram(const Program& program) { return Printer(program).Print(); }

}  // namespace arbiter::arbvp
