// The GLSL of the NV ALU instructions (emit_nv.h), each with the exact semantics of its
// specification section (NV_vertex_program2_option 2.14.5.28-42, NV_fragment_program_option
// 3.11.5.30-47, NV_fragment_program2 3.11.5.48-51).
#include "emit/emit_nv.h"

#include <fmt/format.h>

#include "emit/emit_shapes.h"

namespace arbiter::arbvp::emit {
namespace {

// The pack and unpack instructions read or form the raw bits of a float32, and GLSL 1.10
// has no bit casts (floatBitsToUint is GLSL 3.30's, and no extension of GL 2.x adds it).
// Arithmetic cannot stand in for them: packed bytes make NaN payloads and denormals, which
// float arithmetic neither keeps nor forms. The translation refuses them with a line GLSL
// rejects, naming the instruction.
std::string Refused(const Context& ctx, const Instruction& inst) {
  return fmt::format(
      "#error arbiter cannot translate {} to {}: it needs the bits of a float "
      "(floatBitsToUint, GLSL 3.30 and ES 3.00)\n",
      GetOpcodeInfo(inst.op).name, ctx.target.title);
}
// A constant result replicated to the written components (SFL, STR).
std::string Constant(Context& ctx, const Instruction& inst, const char* value) {
  return Assign(ctx, inst, [&](const Comps& comps) {
    return Replicate({value, 1, true}, static_cast<int>(comps.size()));
  });
}

// A dot product replicated to the written components.
std::string DotOf(Context& ctx, const Instruction& inst, const std::string& dot) {
  return Assign(ctx, inst, [&](const Comps& comps) {
    return Replicate({dot, 1, false}, static_cast<int>(comps.size()));
  });
}

std::string AddressName(const Context& ctx, int var) {
  return ctx.var_names[static_cast<size_t>(var)];
}

}  // namespace

// The components of an address register: ivec4 in NV vertex programs (2.14.3.5: "a set of
// four-component signed integer vectors"); NV_fragment_program2's A0.x is the loop index of
// the innermost LOOP block, "clamped to be greater than or equal to 0" (3.11.3.Y).
std::string AddressComponent(const Context& ctx, const SrcOperand& src) {
  if (!ctx.IsVertex()) {
    std::string index = ctx.flow == FlowMode::Machine ? "arb_a0"
                        : ctx.open_loops.empty()      ? "0"
                                                 : fmt::format("arb_a0_{}", ctx.open_loops.back());
    return fmt::format("({0} < 0 ? 0 : {0})", index);  // GLSL 1.10 has no integer max()
  }
  std::string name = AddressName(ctx, src.address_var);
  if (!ctx.program.Nv()) return name;
  return fmt::format("{}.{}", name, "xyzw"[src.address_component & 3]);
}

std::string AssignAddress(Context& ctx, const Instruction& inst,
                          const std::function<std::string(const Comps&)>& value) {
  const std::string a = AddressName(ctx, inst.dst.var);
  Comps comps;
  for (int c = 0; c < 4; ++c) {
    if (inst.dst.mask & (1u << c)) comps.push_back(c);
  }
  const std::string v = value(comps);
  if (NeedsCcWrite(inst)) {
    return CcWrite(
        ctx, inst, comps, {v, static_cast<int>(comps.size()), true},
        [&](int c) { return fmt::format("{}.{}", a, "xyzw"[c]); }, true);
  }
  if (comps == AllComps()) return fmt::format("{} = {};\n", a, v);
  return fmt::format("{}.{} = {};\n", a, Letters(comps), v);
}

// An address result: "each component of the result vector is clamped to [-512, +511], the
// range of representable address register components" (NV_vertex_program2 2.14.5.2). GLSL
// 1.10 clamps floats only.
std::string AddressResult(const std::string& v, const Comps& comps) {
  if (comps.size() == 1) return fmt::format("int(clamp({}, -512.0, 511.0))", v);
  return fmt::format("ivec{}(clamp({}, -512.0, 511.0))", comps.size(), v);
}

// ARA: (x + z, y + w, x + z, y + w) of the address register operand.
std::string ARA(Context& ctx, const Instruction& inst) {
  const std::string a = AddressName(ctx, Src(inst, 0).var);
  return AssignAddress(ctx, inst, [&](const Comps& comps) {
    std::string sum = fmt::format("vec4({0}.xyxy + {0}.zwzw)", a);
    return AddressResult(comps == AllComps() ? sum : fmt::format("{}.{}", sum, Letters(comps)),
                         comps);
  });
}

// ARL under NV_vertex_program2: "a component-wise floor operation to generate a signed
// integer result vector".
std::string ArlNv(Context& ctx, const Instruction& inst) {
  return AssignAddress(ctx, inst, [&](const Comps& comps) {
    return AddressResult(fmt::format("floor({})", Source(ctx, Src(inst, 0), comps).text), comps);
  });
}

// ARR: round to nearest, "if the fractional portion of the operand is 0.5, round() selects
// the nearest even integer" (GLSL 1.10 has no roundEven: see arb_round_even).
std::string ARR(Context& ctx, const Instruction& inst) {
  ctx.helpers.insert(Helper::RoundEven);
  return AssignAddress(ctx, inst, [&](const Comps& comps) {
    return AddressResult(fmt::format("arb_round_even({})", Source(ctx, Src(inst, 0), comps).text),
                         comps);
  });
}

// DDX, DDY: "approximate partial derivatives ... with respect to the X (Y) window
// coordinate", which is what dFdx and dFdy compute.
std::string DDX(Context& ctx, const Instruction& inst) {
  return Componentwise(
      ctx, inst, [](const auto& a, int w) { return Call(fmt::format("dFdx({})", a[0].text), w); });
}
std::string DDY(Context& ctx, const Instruction& inst) {
  return Componentwise(
      ctx, inst, [](const auto& a, int w) { return Call(fmt::format("dFdy({})", a[0].text), w); });
}

// DIV: each component of the vector divided by the scalar.
std::string DIV(Context& ctx, const Instruction& inst) {
  return Assign(ctx, inst, [&](const Comps& comps) {
    Expr a = Source(ctx, Src(inst, 0), comps);
    Expr s = Source(ctx, Src(inst, 1), {0});
    if (ctx.Mutated(Mutation::DivByVector)) {
      // The operand's register read as a vector, its scalar selector ignored.
      SrcOperand vector = Src(inst, 1);
      vector.swizzle = {Swz::X, Swz::Y, Swz::Z, Swz::W};
      s = Source(ctx, vector, comps);
    }
    return Expr{fmt::format("{} / {}", a.text, s.atomic ? s.text : "(" + s.text + ")"),
                static_cast<int>(comps.size()), false};
  });
}

// DP2: a.x * b.x + a.y * b.y; DP2A adds c.x.
std::string DP2(Context& ctx, const Instruction& inst) {
  return DotOf(ctx, inst,
               fmt::format("dot({}, {})", Source(ctx, Src(inst, 0), {0, 1}).text,
                           Source(ctx, Src(inst, 1), {0, 1}).text));
}
std::string DP2A(Context& ctx, const Instruction& inst) {
  return DotOf(
      ctx, inst,
      fmt::format("dot({}, {}) + {}", Source(ctx, Src(inst, 0), {0, 1}).text,
                  Source(ctx, Src(inst, 1), {0, 1}).text, Source(ctx, Src(inst, 2), {0}).text));
}

// NRM: xyz * rsq(xyz . xyz); "the w component of the result is undefined": we write 1.0,
// as XPD's w.
std::string NRM(Context& ctx, const Instruction& inst) {
  std::string v = Source(ctx, Src(inst, 0), {0, 1, 2}).text;
  return WholeVector(ctx, inst,
                     Call(fmt::format("vec4({0} * inversesqrt(dot({0}, {0})), 1.0)", v), 4));
}

namespace {

// The packing instructions (NV_fragment_program_option 3.11.5.23-26): 32 bits made of the
// operand's components, x in the least significant, as the float they form, replicated. Only
// dialects with floatBitsToUint get here (FindUntranslatable).
std::string Packed(Context& ctx, const Instruction& inst, const std::string& bits) {
  if (!ctx.target.modern) return Refused(ctx, inst);
  ctx.helpers.insert(Helper::Pack);
  return WholeVector(ctx, inst, Call(fmt::format("vec4(uintBitsToFloat({}))", bits), 4));
}

}  // namespace

std::string PK2H(Context& ctx, const Instruction& inst) {
  auto s = [&](int c) { return Source(ctx, Src(inst, 0), {c}).text; };
  return Packed(ctx, inst,
                fmt::format("arb_half_bits({}) | (arb_half_bits({}) << 16)", s(0), s(1)));
}
std::string PK2US(Context& ctx, const Instruction& inst) {
  auto f = [&](int c) {
    return fmt::format("arb_pack_field({}, 0.0, 1.0, 65535.0, 0.0)",
                       Source(ctx, Src(inst, 0), {c}).text);
  };
  return Packed(ctx, inst, fmt::format("{} | ({} << 16)", f(0), f(1)));
}
namespace {

// PK4B: round(127 * clamp(v, -128/127, 1) + 128); PK4UB: round(255 * clamp(v, 0, 1)).
std::string PackBytes(Context& ctx, const Instruction& inst, const char* range) {
  std::string bits;
  for (int c = 0; c < 4; ++c) {
    bits += fmt::format("{}(arb_pack_field({}, {}) << {}u)", c ? " | " : "",
                        Source(ctx, Src(inst, 0), {c}).text, range, 8 * c);
  }
  return Packed(ctx, inst, bits);
}
}  // namespace

std::string PK4B(Context& ctx, const Instruction& inst) {
  return PackBytes(ctx, inst, "-128.0 / 127.0, 1.0, 127.0, 128.0");
}
std::string PK4UB(Context& ctx, const Instruction& inst) {
  return PackBytes(ctx, inst, "0.0, 1.0, 255.0, 0.0");
}

// RCC: the reciprocal clamped to [2^-64, 2^64] or [-2^64, -2^-64] (see arb_rcc).
std::string RCC(Context& ctx, const Instruction& inst) {
  ctx.helpers.insert(Helper::Rcc);
  return ScalarOp(ctx, inst, [](const auto& a) { return fmt::format("arb_rcc({})", a[0].text); });
}

// RFL: the direction b reflected about the axis a (see arb_rfl; GLSL's reflect() takes a
// unit normal and the opposite sign). Its w is undefined.
std::string RFL(Context& ctx, const Instruction& inst) {
  ctx.helpers.insert(Helper::Rfl);
  Expr e3 = Call(fmt::format("arb_rfl({}, {})", Source(ctx, Src(inst, 0), {0, 1, 2}).text,
                             Source(ctx, Src(inst, 1), {0, 1, 2}).text),
                 3);
  return Assign(ctx, inst, [&](const Comps& comps) {
    if (comps == Comps{0, 1, 2}) return e3;
    // w is undefined (arb-rfl-writes-w): 0.0 stands for it.
    if (comps.back() == 3) return Select(Call(fmt::format("vec4({}, 0.0)", e3.text), 4), comps);
    return Select(e3, comps);
  });
}

// The "set on" comparisons: 1.0 where the comparison holds, else 0.0; SFL and STR compare
// nothing.
std::string SEQ(Context& ctx, const Instruction& inst) {
  if (ctx.Mutated(Mutation::SeqSneSwapped)) return Compare(ctx, inst, "!=", "notEqual");
  return Compare(ctx, inst, "==", "equal");
}
std::string SFL(Context& ctx, const Instruction& inst) { return Constant(ctx, inst, "0.0"); }
std::string SGT(Context& ctx, const Instruction& inst) {
  return Compare(ctx, inst, ">", "greaterThan");
}
std::string SLE(Context& ctx, const Instruction& inst) {
  return Compare(ctx, inst, "<=", "lessThanEqual");
}
std::string SNE(Context& ctx, const Instruction& inst) {
  if (ctx.Mutated(Mutation::SeqSneSwapped)) return Compare(ctx, inst, "==", "equal");
  return Compare(ctx, inst, "!=", "notEqual");
}
std::string STR(Context& ctx, const Instruction& inst) { return Constant(ctx, inst, "1.0"); }

// SSG: 1.0, 0.0 or -1.0 as the component is positive, zero or negative (arb_ssg: GLSL's
// sign() leaves NaN undefined).
std::string SSG(Context& ctx, const Instruction& inst) {
  ctx.helpers.insert(Helper::Ssg);
  return Componentwise(ctx, inst, [](const auto& a, int w) {
    return Call(fmt::format("arb_ssg({})", a[0].text), w);
  });
}

namespace {

// The unpacking instructions (3.11.5.37-40): the bits of the operand's x, in fields from the
// least significant; two-field forms repeat them in z and w.
std::string Unpacked(Context& ctx, const Instruction& inst, const std::string& pattern) {
  if (!ctx.target.modern) return Refused(ctx, inst);
  ctx.helpers.insert(Helper::Pack);
  const std::string bits = fmt::format("floatBitsToUint({})", Source(ctx, Src(inst, 0), {0}).text);
  return WholeVector(ctx, inst, Call(fmt::format(fmt::runtime(pattern), bits), 4));
}
}  // namespace

std::string UP2H(Context& ctx, const Instruction& inst) {
  return Unpacked(ctx, inst,
                  "vec4(arb_half_value({0} & 0xFFFFu), arb_half_value({0} >> 16),"
                  " arb_half_value({0} & 0xFFFFu), arb_half_value({0} >> 16))");
}
namespace {

// Components 0..3 read field n % count of `width` bits: (field + offset) / divisor.
std::string UnpackFields(Context& ctx, const Instruction& inst, int count, int width,
                         const char* offset, const char* divisor) {
  std::string fields;
  for (int n = 0; n < 4; ++n) {
    fields += fmt::format("{}arb_unpack_field({{0}}, {}u, {}u, {}, {})", n ? ", " : "", n % count,
                          width, offset, divisor);
  }
  return Unpacked(ctx, inst, "vec4(" + fields + ")");
}
}  // namespace

std::string UP2US(Context& ctx, const Instruction& inst) {
  return UnpackFields(ctx, inst, 2, 16, "0.0", "65535.0");
}
std::string UP4B(Context& ctx, const Instruction& inst) {
  return UnpackFields(ctx, inst, 4, 8, "-128.0", "127.0");
}
std::string UP4UB(Context& ctx, const Instruction& inst) {
  return UnpackFields(ctx, inst, 4, 8, "0.0", "255.0");
}

// X2D: a.xy + (b.x * c.x + b.y * c.y, b.x * c.z + b.y * c.w), written to (x, y, x, y) in
// the specification's order of operations.
std::string X2D(Context& ctx, const Instruction& inst) {
  return PerComponent(ctx, inst, [&](int c) {
    auto s = [&](size_t i, int comp) { return Source(ctx, Src(inst, i), {comp}).text; };
    const bool x = c == 0 || c == 2;
    return fmt::format("{} + {} * {} + {} * {}", s(0, x ? 0 : 1), s(1, 0), s(2, x ? 0 : 2), s(1, 1),
                       s(2, x ? 1 : 3));
  });
}

}  // namespace arbiter::arbvp::emit
