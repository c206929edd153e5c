// One translation function per ARB opcode, in the order of opcodes.def: each returns the
// GLSL statement(s) for one instruction with the exact ARB semantics (ARBvp 2.14.5,
// ARBfp 3.11.5 and 3.11.6).
#include <fmt/format.h>

#include "emit/emit_context.h"
#include "emit/emit_flow.h"
#include "emit/emit_nv.h"
#include "emit/emit_shapes.h"
#include "emit/emit_texture.h"

namespace arbiter::arbvp::emit {
namespace {

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
  if (ctx.program.Nv()) return ArlNv(ctx, inst);
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
  // NV_fragment_program_option: KIL <ccTest> kills when the test holds for any component.
  if (inst.cond.present) return fmt::format("if ({}) discard;\n", CcAnyTest(ctx, inst.cond));
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
  ctx.conversion = InstructionConversion(ctx, inst);
  std::string out = kEmitters[static_cast<size_t>(inst.op)](ctx, inst);
  ctx.conversion = Conversion::None;
  return out;
}

}  // namespace arbiter::arbvp::emit
