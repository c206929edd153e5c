// One translation function per ARB opcode, in the order of opcodes.def: each returns the
// GLSL statement(s) for one instruction with the exact ARB semantics (ARBvp 2.14.5,
// ARBfp 3.11.5 and 3.11.6).
#include <fmt/format.h>

#include "emit/emit_context.h"
#include "emit/emit_nv.h"

namespace arbiter::arbvp::emit {
namespace {

const SrcOperand& Src(const Instruction& inst, size_t i) { return inst.src[i]; }

// A component-wise operation: operands narrowed to the written components, so that
// `ADD t.xz, a, b` becomes `t.xz = a.xz + b.xz;`.
template <typename F>
std::string Componentwise(Context& ctx, const Instruction& inst, F op) {
  return Assign(ctx, inst, [&](const Comps& comps) {
    std::vector<Expr> a;
    for (int i = 0; i < inst.src_count; ++i)
      a.push_back(Source(ctx, Src(inst, static_cast<size_t>(i)), comps));
    return op(a, static_cast<int>(comps.size()));
  });
}

// A scalar operation: the result of one float expression replicated to the written
// components (ARBvp 2.14.5: "the scalar result is replicated").
template <typename F>
std::string ScalarOp(Context& ctx, const Instruction& inst, F op) {
  return Assign(ctx, inst, [&](const Comps& comps) {
    std::vector<Expr> a;
    for (int i = 0; i < inst.src_count; ++i)
      a.push_back(Source(ctx, Src(inst, static_cast<size_t>(i)), {0}));
    return Replicate({op(a), 1, false}, static_cast<int>(comps.size()));
  });
}

// An operation producing a whole vec4, of which the written components are selected.
std::string WholeVector(Context& ctx, const Instruction& inst, const Expr& e4) {
  return Assign(ctx, inst, [&](const Comps& comps) { return Select(e4, comps); });
}

// An operation defined component by component (`component(c)` gives component c).
template <typename F>
std::string PerComponent(Context& ctx, const Instruction& inst, F component) {
  return Assign(ctx, inst, [&](const Comps& comps) {
    std::vector<std::string> parts;
    for (int c : comps) parts.push_back(component(c));
    return Construct(parts);
  });
}

Expr Call(std::string text, int width) { return {std::move(text), width, true}; }

std::string ABS(Context& ctx, const Instruction& inst) {
  return Componentwise(
      ctx, inst, [](const auto& a, int w) { return Call(fmt::format("abs({})", a[0].text), w); });
}
std::string ADD(Context& ctx, const Instruction& inst) {
  return Componentwise(ctx, inst, [](const auto& a, int w) {
    return Expr{fmt::format("{} + {}", a[0].text, a[1].text), w, false};
  });
}

// ARL: A0.x = floor(s) as an integer (ARBvp 2.14.5.3).
std::string ARL(Context& ctx, const Instruction& inst) {
  std::string a = ctx.var_names[static_cast<size_t>(inst.dst.var)];
  std::string s = Source(ctx, Src(inst, 0), {0}).text;
  if (ctx.Mutated(Mutation::ArlTruncate)) return fmt::format("{} = int({});\n", a, s);
  return fmt::format("{} = int(floor({}));\n", a, s);
}

// CMP: per component, a < 0 ? b : c (a NaN compares false and selects c, as in ARB).
std::string CMP(Context& ctx, const Instruction& inst) {
  const char* op = ctx.Mutated(Mutation::CmpLessEqual) ? "<=" : "<";
  return PerComponent(ctx, inst, [&](int c) {
    return fmt::format("{} {} 0.0 ? {} : {}", Source(ctx, Src(inst, 0), {c}).text, op,
                       Source(ctx, Src(inst, 1), {c}).text, Source(ctx, Src(inst, 2), {c}).text);
  });
}
std::string COS(Context& ctx, const Instruction& inst) {
  return ScalarOp(ctx, inst, [](const auto& a) { return fmt::format("cos({})", a[0].text); });
}

// Dot products read their own components, whatever the write mask.
std::string Dot(Context& ctx, const Instruction& inst, const Comps& comps, bool homogeneous) {
  std::string text = fmt::format("dot({}, {})", Source(ctx, Src(inst, 0), comps).text,
                                 Source(ctx, Src(inst, 1), comps).text);
  if (homogeneous && !ctx.Mutated(Mutation::DphNoW)) {
    text += " + " + Source(ctx, Src(inst, 1), {3}).text;
  }
  Expr e{text, 1, !homogeneous || ctx.Mutated(Mutation::DphNoW)};
  return Assign(ctx, inst,
                [&](const Comps& c) { return Replicate(e, static_cast<int>(c.size())); });
}
std::string DP3(Context& ctx, const Instruction& inst) { return Dot(ctx, inst, {0, 1, 2}, false); }
std::string DP4(Context& ctx, const Instruction& inst) { return Dot(ctx, inst, AllComps(), false); }
// DPH: a.xyz . b.xyz + b.w
std::string DPH(Context& ctx, const Instruction& inst) { return Dot(ctx, inst, {0, 1, 2}, true); }

// DST: (1, a.y * b.y, a.z, b.w)
std::string DST(Context& ctx, const Instruction& inst) {
  bool swap = ctx.Mutated(Mutation::DstComponents);
  return PerComponent(ctx, inst, [&](int c) -> std::string {
    if (swap && (c == 1 || c == 2)) c = 3 - c;
    switch (c) {
      case 0:
        return "1.0";
      case 1:
        return fmt::format("{} * {}", Source(ctx, Src(inst, 0), {1}).text,
                           Source(ctx, Src(inst, 1), {1}).text);
      case 2:
        return Source(ctx, Src(inst, 0), {2}).text;
      default:
        return Source(ctx, Src(inst, 1), {3}).text;
    }
  });
}
std::string EX2(Context& ctx, const Instruction& inst) {
  return ScalarOp(ctx, inst, [](const auto& a) { return fmt::format("exp2({})", a[0].text); });
}
// EXP (vertex programs): arb_exp(t) = (2^floor(t), t - floor(t), 2^t, 1).
std::string EXP(Context& ctx, const Instruction& inst) {
  ctx.helpers.insert(Helper::Exp);
  return WholeVector(ctx, inst,
                     Call(fmt::format("arb_exp({})", Source(ctx, Src(inst, 0), {0}).text), 4));
}
std::string FLR(Context& ctx, const Instruction& inst) {
  return Componentwise(
      ctx, inst, [](const auto& a, int w) { return Call(fmt::format("floor({})", a[0].text), w); });
}
// FRC: x - floor(x), which is GLSL's fract().
std::string FRC(Context& ctx, const Instruction& inst) {
  bool trunc = ctx.Mutated(Mutation::FrcTruncate);
  return Componentwise(ctx, inst, [&](const auto& a, int w) {
    if (!trunc) return Call(fmt::format("fract({})", a[0].text), w);
    std::string ints = w == 1 ? "float(int({}))" : fmt::format("vec{0}(ivec{0}({{}}))", w);
    return Expr{a[0].text + " - " + fmt::format(fmt::runtime(ints), a[0].text), w, false};
  });
}

// KIL: discard if any component is negative; a NaN is not negative and does not kill.
std::string KIL(Context& ctx, const Instruction& inst) {
  if (ctx.Mutated(Mutation::KilOnlyX)) {
    return fmt::format("if ({} < 0.0) discard;\n", Source(ctx, Src(inst, 0), {0}).text);
  }
  std::string v = Source(ctx, Src(inst, 0), AllComps()).text;
  if (ctx.Mutated(Mutation::KilOnNaN)) {
    return fmt::format("if (!all(greaterThanEqual({}, vec4(0.0)))) discard;\n", v);
  }
  return fmt::format("if (any(lessThan({}, vec4(0.0)))) discard;\n", v);
}
std::string LG2(Context& ctx, const Instruction& inst) {
  return ScalarOp(ctx, inst, [](const auto& a) { return fmt::format("log2({})", a[0].text); });
}
// LIT: see arb_lit (emit_helpers.cpp).
std::string LIT(Context& ctx, const Instruction& inst) {
  ctx.helpers.insert(Helper::Lit);
  return WholeVector(
      ctx, inst, Call(fmt::format("arb_lit({})", Source(ctx, Src(inst, 0), AllComps()).text), 4));
}
// LOG (vertex programs): see arb_log.
std::string LOG(Context& ctx, const Instruction& inst) {
  ctx.helpers.insert(Helper::Log);
  return WholeVector(ctx, inst,
                     Call(fmt::format("arb_log({})", Source(ctx, Src(inst, 0), {0}).text), 4));
}
// LRP: a * b + (1 - a) * c = mix(c, b, a).
std::string LRP(Context& ctx, const Instruction& inst) {
  bool swap = ctx.Mutated(Mutation::LrpOperandOrder);
  return Componentwise(ctx, inst, [&](const auto& a, int w) {
    return Call(
        fmt::format("mix({}, {}, {})", a[swap ? 1 : 2].text, a[swap ? 2 : 1].text, a[0].text), w);
  });
}
std::string MAD(Context& ctx, const Instruction& inst) {
  return Componentwise(ctx, inst, [](const auto& a, int w) {
    return Expr{fmt::format("{} * {} + {}", a[0].text, a[1].text, a[2].text), w, false};
  });
}
std::string MAX(Context& ctx, const Instruction& inst) {
  return Componentwise(ctx, inst, [](const auto& a, int w) {
    return Call(fmt::format("max({}, {})", a[0].text, a[1].text), w);
  });
}
std::string MIN(Context& ctx, const Instruction& inst) {
  return Componentwise(ctx, inst, [](const auto& a, int w) {
    return Call(fmt::format("min({}, {})", a[0].text, a[1].text), w);
  });
}
std::string MOV(Context& ctx, const Instruction& inst) {
  return Componentwise(ctx, inst, [](const auto& a, int) { return a[0]; });
}
std::string MUL(Context& ctx, const Instruction& inst) {
  return Componentwise(ctx, inst, [](const auto& a, int w) {
    return Expr{fmt::format("{} * {}", a[0].text, a[1].text), w, false};
  });
}
std::string POW(Context& ctx, const Instruction& inst) {
  bool swap = ctx.Mutated(Mutation::PowOperandsSwapped);
  return ScalarOp(ctx, inst, [&](const auto& a) {
    return fmt::format("pow({}, {})", a[swap ? 1 : 0].text, a[swap ? 0 : 1].text);
  });
}
std::string RCP(Context& ctx, const Instruction& inst) {
  return ScalarOp(ctx, inst, [](const auto& a) { return fmt::format("1.0 / {}", a[0].text); });
}
// RSQ: 1 / sqrt(|x|): the specs take the absolute value.
std::string RSQ(Context& ctx, const Instruction& inst) {
  bool no_abs = ctx.Mutated(Mutation::RsqNoAbs);
  return ScalarOp(ctx, inst, [&](const auto& a) {
    return no_abs ? fmt::format("inversesqrt({})", a[0].text)
                  : fmt::format("inversesqrt(abs({}))", a[0].text);
  });
}
// SCS: (cos(a), sin(a), z, w) with z and w undefined by the spec; we write 0.0 and 1.0.
std::string SCS(Context& ctx, const Instruction& inst) {
  bool swap = ctx.Mutated(Mutation::ScsSinCosSwapped);
  std::string a = Source(ctx, Src(inst, 0), {0}).text;
  return PerComponent(ctx, inst, [&](int c) -> std::string {
    if (c >= 2) return c == 2 ? "0.0" : "1.0";
    return fmt::format("{}({})", (c == 0) != swap ? "cos" : "sin", a);
  });
}

// SGE / SLT: 1.0 where the comparison holds, else 0.0 (false for NaN).
std::string Compare(Context& ctx, const Instruction& inst, const char* op, const char* function) {
  return Componentwise(ctx, inst, [&](const auto& a, int w) {
    if (w == 1) return Call(fmt::format("float({} {} {})", a[0].text, op, a[1].text), 1);
    return Call(fmt::format("vec{}({}({}, {}))", w, function, a[0].text, a[1].text), w);
  });
}
std::string SGE(Context& ctx, const Instruction& inst) {
  if (ctx.Mutated(Mutation::SgeStrict)) return Compare(ctx, inst, ">", "greaterThan");
  return Compare(ctx, inst, ">=", "greaterThanEqual");
}
std::string SIN(Context& ctx, const Instruction& inst) {
  return ScalarOp(ctx, inst, [](const auto& a) { return fmt::format("sin({})", a[0].text); });
}
std::string SLT(Context& ctx, const Instruction& inst) {
  return Compare(ctx, inst, "<", "lessThan");
}
std::string SUB(Context& ctx, const Instruction& inst) {
  return Componentwise(ctx, inst, [](const auto& a, int w) {
    return Expr{fmt::format("{} - {}", a[0].text, a[1].text), w, false};
  });
}
// SWZ: a constructor of 0, 1 and signed components.
std::string SWZ(Context& ctx, const Instruction& inst) {
  return PerComponent(ctx, inst, [&](int c) { return SwizzleComponent(ctx, Src(inst, 0), c); });
}

// Texture sampling. The coordinate components each target reads; shadow targets take the
// depth reference from r (ARB_fragment_program_shadow).
Comps CoordComps(TexTarget target) {
  switch (target) {
    case TexTarget::Tex1D:
      return {0};
    case TexTarget::Tex2D:
    case TexTarget::Rect:
      return {0, 1};
    case TexTarget::Tex3D:
    case TexTarget::Cube:
    case TexTarget::Shadow1D:
    case TexTarget::Shadow2D:
    case TexTarget::ShadowRect:
      return {0, 1, 2};
  }
  return {0, 1};
}

std::string_view SampleFunction(TexTarget target) {
  switch (target) {
    case TexTarget::Tex1D:
      return "texture1D";
    case TexTarget::Tex2D:
      return "texture2D";
    case TexTarget::Tex3D:
      return "texture3D";
    case TexTarget::Cube:
      return "textureCube";
    case TexTarget::Rect:
      return "texture2DRect";
    case TexTarget::Shadow1D:
      return "shadow1D";
    case TexTarget::Shadow2D:
      return "shadow2D";
    case TexTarget::ShadowRect:
      return "shadow2DRect";
  }
  return "texture2D";
}

enum class SampleKind { Plain, Projective, Bias };

std::string Sample(Context& ctx, const Instruction& inst, SampleKind kind) {
  if (kind == SampleKind::Projective && ctx.Mutated(Mutation::TxpNoDivide))
    kind = SampleKind::Plain;
  TexTarget target = inst.target;
  ctx.samplers[inst.tex_unit] = target;
  if (target == TexTarget::Rect || target == TexTarget::ShadowRect) ctx.needs_rect = true;
  std::string sampler = SamplerName(inst.tex_unit);
  std::string f(SampleFunction(target));
  const SrcOperand& coord = Src(inst, 0);
  std::string text;
  if (kind == SampleKind::Projective && target == TexTarget::Cube) {
    // GLSL has no textureCubeProj: divide s, t, r by q ourselves.
    text = fmt::format("{}({}, {} / {})", f, sampler, Source(ctx, coord, {0, 1, 2}).text,
                       Source(ctx, coord, {3}).text);
  } else if (kind == SampleKind::Projective) {
    // The ...Proj functions with a vec4 divide the coordinates (and r) by q.
    text = fmt::format("{}Proj({}, {})", f, sampler, Source(ctx, coord, AllComps()).text);
  } else {
    text = fmt::format("{}({}, {}", f, sampler, Source(ctx, coord, CoordComps(target)).text);
    // TXB: w is the LOD bias. Rectangle textures have no mipmaps and GLSL no bias form.
    bool rect = target == TexTarget::Rect || target == TexTarget::ShadowRect;
    if (kind == SampleKind::Bias && !rect) text += ", " + Source(ctx, coord, {3}).text;
    text += ")";
  }
  return WholeVector(ctx, inst, Call(text, 4));
}
std::string TEX(Context& ctx, const Instruction& inst) {
  return Sample(ctx, inst, SampleKind::Plain);
}
std::string TXB(Context& ctx, const Instruction& inst) {
  return Sample(ctx, inst, SampleKind::Bias);
}
std::string TXP(Context& ctx, const Instruction& inst) {
  return Sample(ctx, inst, SampleKind::Projective);
}

// XPD: the cross product of a.xyz and b.xyz; w is undefined by the spec: we write 1.0
// (what Mesa's own ARB implementation gives).
std::string XPD(Context& ctx, const Instruction& inst) {
  bool swap = ctx.Mutated(Mutation::XpdOperandOrder);
  std::string a = Source(ctx, Src(inst, swap ? 1 : 0), {0, 1, 2}).text;
  std::string b = Source(ctx, Src(inst, swap ? 0 : 1), {0, 1, 2}).text;
  std::string cross = fmt::format("cross({}, {})", a, b);
  return Assign(ctx, inst, [&](const Comps& comps) {
    if (comps.back() == 3) return Select(Call(fmt::format("vec4({}, 1.0)", cross), 4), comps);
    if (comps == Comps{0, 1, 2}) return Call(cross, 3);
    return Expr{cross + "." + Letters(comps), static_cast<int>(comps.size()), true};
  });
}

using EmitFn = std::string (*)(Context&, const Instruction&);

// Indexed by Opcode: one row per opcodes.def row.
constexpr EmitFn kEmitters[] = {
#define ARBVP_OPCODE(name, vp, fp, signature, klass, vp_mods, fp_mods, fp2_mods, reads, spec) &name,
#include "arbiter/arbvp/opcodes.def"
#undef ARBVP_OPCODE
};

}  // namespace

std::string EmitInstruction(Context& ctx, const Instruction& inst) {
  return kEmitters[static_cast<size_t>(inst.op)](ctx, inst);
}

}  // namespace arbiter::arbvp::emit
