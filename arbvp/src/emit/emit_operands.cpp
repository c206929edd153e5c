// Source operands (swizzle, |abs|, negation, relative addressing, folded constants, NV
// precision) and destination writes (write mask, _SAT, _SSAT, NV precision and condition codes).
#include <fmt/format.h>

#include <cmath>

#include "emit/emit_context.h"

namespace arbiter::arbvp::emit {
namespace {

bool Negated(const Context& ctx, const SrcOperand& src) {
  return src.negate && !ctx.Mutated(Mutation::NegationDropped);
}

// A constant operand is folded: its swizzled, negated components as a literal.
Expr FoldConstant(const Context& ctx, const Binding& b, const SrcOperand& src, const Comps& comps) {
  std::vector<float> values;
  for (int c : comps) {
    Swz s = src.swizzle[static_cast<size_t>(c)];
    float v = s == Swz::Zero ? 0.0f : s == Swz::One ? 1.0f : b.value[static_cast<size_t>(s)];
    if (src.abs) v = std::fabs(v);
    values.push_back(Negated(ctx, src) ? -v : v);
  }
  bool same = true;
  for (float v : values) same = same && FormatFloat(v) == FormatFloat(values[0]);
  if (values.size() == 1) return {FormatFloat(values[0]), 1, values[0] >= 0.0f};
  if (same) return Replicate({FormatFloat(values[0]), 1, true}, static_cast<int>(values.size()));
  std::vector<std::string> parts;
  for (float v : values) parts.push_back(FormatFloat(v));
  return Construct(parts);
}

// A relative offset A0.x + k as GLSL int arithmetic.
std::string RelativeIndex(const Context& ctx, const SrcOperand& src) {
  std::string a = AddressComponent(ctx, src);
  if (src.index > 0) return fmt::format("{} + {}", a, src.index);
  if (src.index < 0) return fmt::format("{} - {}", a, -src.index);
  return a;
}

// The operand before the conversion to the instruction's precision.
Expr Load(Context& ctx, const SrcOperand& src, const Comps& comps) {
  const Variable& var = ctx.program.vars[static_cast<size_t>(src.var)];
  Expr base;
  switch (var.kind) {
    case VarKind::Temp:
    case VarKind::Address:
      base = {ctx.var_names[static_cast<size_t>(src.var)], 4, true};
      break;
    case VarKind::Attrib:
    case VarKind::Output:
    case VarKind::Param: {
      // Relative addressing of a PARAM array, and of the attribute arrays of
      // NV_vertex_program3 (vertex.attrib, vertex.texcoord) and NV_fragment_program2
      // (fragment.texcoord[A0.x + n]) when the variable binds every element.
      if (src.relative) {
        base = {fmt::format("{}({})", RelativeReaderName(ctx, src.var), RelativeIndex(ctx, src)), 4,
                true};
        break;
      }
      const Binding& b = var.bindings.at(src.indexed ? static_cast<size_t>(src.index) : 0);
      if (b.kind == BindingKind::Constant) return FoldConstant(ctx, b, src, comps);
      base = ReadBinding(ctx, b);
      break;
    }
  }
  std::string letters;
  for (int c : comps) {
    Swz s = src.swizzle[static_cast<size_t>(c)];
    letters += s <= Swz::W ? "xyzw"[static_cast<int>(s)] : 'x';
  }
  Expr out = base;
  bool in_xyz = letters.find('w') == std::string::npos;
  if (letters != "xyzw" && !base.parts.empty() && comps.size() == 1) {
    out = {base.parts[static_cast<size_t>(std::string("xyzw").find(letters[0]))], 1, true};
  } else if (letters != "xyzw" && in_xyz && !base.xyz.empty()) {
    out = {letters == "xyz" ? base.xyz : base.xyz + "." + letters, static_cast<int>(comps.size()),
           true};
  } else if (letters != "xyzw") {
    out = {(base.atomic ? base.text : "(" + base.text + ")") + "." + letters,
           static_cast<int>(comps.size()), true};
  }
  if (src.abs) out = {fmt::format("abs({})", out.text), out.width, true};
  if (Negated(ctx, src)) out = {"-" + out.text, out.width, false};
  return out;
}

}  // namespace

// The NV operand modifiers after the swizzle: |abs|, then the sign, then the conversion to
// the instruction's precision (NV_fragment_program 3.11.4.3, VectorLoad).
Expr Source(Context& ctx, const SrcOperand& src, const Comps& comps) {
  return Convert(ctx, Load(ctx, src, comps), ctx.conversion);
}

// SWZ: each component is 0, 1 or a source component, with its own sign (ARBvp 2.14.5.26).
std::string SwizzleComponent(Context& ctx, const SrcOperand& src, int comp) {
  Swz s = src.swizzle[static_cast<size_t>(comp)];
  bool negate = src.negate != (src.component_negate[static_cast<size_t>(comp)] &&
                               !ctx.Mutated(Mutation::SwzSignLost));
  if (ctx.Mutated(Mutation::NegationDropped)) negate = false;
  if (s == Swz::Zero || s == Swz::One) {
    bool one = (s == Swz::One) != ctx.Mutated(Mutation::SwzZeroOneSwapped);
    return std::string(negate ? "-" : "") + (one ? "1.0" : "0.0");
  }
  SrcOperand plain = src;
  plain.negate = negate;
  plain.component_negate = {false, false, false, false};
  std::swap(plain.swizzle[0], plain.swizzle[static_cast<size_t>(comp)]);
  return Source(ctx, plain, {0}).text;
}

std::string AssignTo(Context& ctx, const Instruction& inst,
                     const std::function<Expr(const Comps&)>& value, const DestTarget& target);

std::string AssignImpl(Context& ctx, const Instruction& inst,
                       const std::function<Expr(const Comps&)>& value) {
  const Variable& var = ctx.program.vars[static_cast<size_t>(inst.dst.var)];
  if (var.kind == VarKind::Temp) {
    DestTarget target;
    target.lvalue = ctx.var_names[static_cast<size_t>(inst.dst.var)];
    return AssignTo(ctx, inst, value, target);
  }
  if (!inst.dst.relative) return AssignTo(ctx, inst, value, ResultTarget(ctx, var.bindings.at(0)));
  // result.texcoord[A0.x + n] (NV_vertex_program3): the element the address selects, by an
  // if-chain of constant indices; outside the array nothing is written (the spec leaves
  // such a write undefined).
  SrcOperand address;
  address.address_var = inst.dst.address_var;
  address.address_component = inst.dst.address_component;
  address.index = inst.dst.index;
  std::string text = fmt::format("{{\n  int arb_element = {};\n", RelativeIndex(ctx, address));
  for (size_t i = 0; i < var.bindings.size(); ++i) {
    text += fmt::format("  {}if (arb_element == {}) {{\n", i == 0 ? "" : "} else ", i);
    std::string body = AssignTo(ctx, inst, value, ResultTarget(ctx, var.bindings[i]));
    for (size_t at = 0; at < body.size();) {
      const size_t eol = body.find('\n', at);
      text += "    " + body.substr(at, eol == std::string::npos ? eol : eol - at + 1);
      at = eol == std::string::npos ? body.size() : eol + 1;
    }
  }
  return text + "  }\n}\n";
}

// Writes `value` to `target` under the instruction's mask, conversions and condition code.
std::string AssignTo(Context& ctx, const Instruction& inst,
                     const std::function<Expr(const Comps&)>& value, const DestTarget& target) {
  uint8_t mask = ctx.Mutated(Mutation::WriteMaskIgnored) ? 0xF : inst.dst.mask;
  // The result at the instruction's precision, clamped (_SAT [0, 1], _SSAT [-1, 1]), then
  // converted to the destination's storage (NV_fragment_program 3.11.4.4).
  auto finish = [&](Expr e) {
    e = Convert(ctx, e, ctx.conversion);
    if (inst.saturate && !ctx.Mutated(Mutation::SaturateDropped)) {
      e = Expr{fmt::format("clamp({}, 0.0, 1.0)", e.text), e.width, true};
    }
    if (inst.signed_saturate) {
      const char* low = ctx.Mutated(Mutation::SsatUnitRange) ? "0.0" : "-1.0";
      e = Expr{fmt::format("clamp({}, {}, 1.0)", e.text, low), e.width, true};
    }
    return Convert(ctx, e, StorageConversion(ctx, inst.dst.var, ctx.conversion));
  };
  Comps comps;
  for (int c = 0; c < 4; ++c) {
    if (mask & (1u << c)) comps.push_back(c);
  }
  if (NeedsCcWrite(inst)) {
    // Every enabled component updates the condition code, even those a float result
    // register does not keep.
    return CcWrite(
        ctx, inst, comps, finish(value(comps)),
        [&](int c) -> std::string {
          if (target.scalar_component < 0) return fmt::format("{}.{}", target.lvalue, "xyzw"[c]);
          return c == target.scalar_component ? target.lvalue : "";
        },
        false);
  }
  if (target.scalar_component >= 0) {
    // A float result register takes one component of the ARB result, if written.
    if (!(mask & (1u << target.scalar_component))) {
      return fmt::format("// (component {} of {} is not written)\n",
                         "xyzw"[target.scalar_component], target.lvalue);
    }
    Expr e = finish(value({target.scalar_component}));
    return fmt::format("{} = {};\n", target.lvalue, e.text);
  }
  Expr e = finish(value(comps));
  if (comps.size() == 4) return fmt::format("{} = {};\n", target.lvalue, e.text);
  return fmt::format("{}.{} = {};\n", target.lvalue, Letters(comps), e.text);
}

}  // namespace arbiter::arbvp::emit
