// The NV instructions' semantics (ops_nv.h): the pseudo-code of NV_vertex_program2_option
// 2.14.5.28-42, NV_vertex_program3 2.14.5.43-48, NV_fragment_program_option 3.11.5.30-47
// and NV_fragment_program2 3.11.5.48-51, 3.11.6.6. Where an instruction is an ARB one on
// other operands (DP2 is DP3 with z = 0, NRM is DP3, RSQ and MUL) it runs ops.cpp's, so
// it shares that code's tolerance model and undefined cases.
#include "exec/ops_nv.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <string>

#include "exec/ops.h"
#include "exec/precision.h"
#include "exec/tolerance.h"

namespace arbiter::arbvp::exec {
namespace {

using D1 = std::array<double, 1>;
using D2 = std::array<double, 2>;

Reg Replicate(Val v) { return {v, v, v, v}; }

// The ARB instruction `op` of ops.cpp on the operands `src`.
Reg RunArb(const OpContext& c, Opcode op, const std::array<Reg, 3>& src) {
  OpContext sub = c;
  sub.src = src;
  return Execute(op, sub);
}

// The operand with its z replaced by `z` (a signed zero keeps the sum's sign unchanged).
Reg WithZ(Reg r, float z) {
  r[2] = Val{z};
  return r;
}

Val Negated(Val v) {
  v.v = -v.v;
  return v;
}

// ---- set on -------------------------------------------------------------------------------

// The comparison instructions: 1 where `pred` holds, else 0; a NaN operand compares false
// (SNE: true). NV_vertex_program2's rules agree for vertex programs, but its issue on NaN
// says the result is NaN there: that case is undefined.
template <typename P>
Reg SetOn(const OpContext& c, const char* name, P pred, bool equality) {
  Reg r;
  for (size_t i = 0; i < 4; ++i) {
    const Val& a = c.src[0][i];
    const Val& b = c.src[1][i];
    float v = pred(a.v, b.v) ? 1.0f : 0.0f;
    float err = 0.0f;
    if (equality) {
      // Not monotone: any overlap of the two boxes may flip equality.
      if (std::isinf(a.err) || std::isinf(b.err)) {
        err = kUnstable;
      } else if ((a.err > 0.0f || b.err > 0.0f) &&
                 std::fabs(Wide(a.v) - Wide(b.v)) <= Wide(a.err) + Wide(b.err)) {
        err = 1.0f;
      }
    } else {
      err = CornerBound<2>(
          v, {a, b}, [&](const D2& x) { return pred(x[0], x[1]) ? 1.0 : 0.0; }, 0.0);
    }
    r[i] = From(v, {a, b}, err);
    if (c.kind == ProgramKind::Vertex && (std::isnan(a.v) || std::isnan(b.v)) &&
        r[i].why == kDefined) {
      r[i].why = c.Undefined(std::string(name) +
                             " of NaN (NV_vertex_program2's rules give 0 or 1, its issues NaN)");
    }
  }
  return r;
}

// ---- packing ------------------------------------------------------------------------------

// One converted component of PK2US, PK4B or PK4UB: round(scale * clamp(x) + offset).
// Unstable where the operand's box, or an exact tie (the specs do not say which way round()
// breaks one), reaches another integer.
struct Packed {
  uint32_t bits = 0;
  bool stable = true;
};
Packed PackComponent(const Val& x, double lo, double hi, double scale, double offset) {
  auto scaled = [&](double t) { return scale * std::clamp(t, lo, hi) + offset; };
  auto tie = [](double t) { return t - std::floor(t) == 0.5; };
  if (std::isnan(x.v)) return {0, false};  // undefined (PackResult)
  const double centre = scaled(Wide(x.v));
  Packed p{static_cast<uint32_t>(std::nearbyint(centre))};
  const double below = scaled(Wide(x.v) - Wide(x.err));
  const double above = scaled(Wide(x.v) + Wide(x.err));
  p.stable = !std::isinf(x.err) && !tie(centre) && !tie(below) && !tie(above) &&
             std::nearbyint(below) == std::nearbyint(above);
  return p;
}

// The packed 32 bits as the float the result register holds, replicated.
Reg PackResult(const OpContext& c, const char* name, uint32_t bits, bool stable,
               std::initializer_list<Val> deps) {
  Val r = From(std::bit_cast<float>(bits), deps, stable ? 0.0f : kUnstable);
  for (const Val& d : deps) {
    if (std::isnan(d.v) && r.why == kDefined) r.why = c.Undefined(std::string(name) + " of NaN");
  }
  return Replicate(r);
}

// PK4B and PK4UB: four bytes, x in the least significant.
Reg PackBytes(const OpContext& c, const char* name, double lo, double hi, double scale,
              double offset) {
  const Reg& a = c.src[0];
  uint32_t bits = 0;
  bool stable = true;
  for (size_t i = 0; i < 4; ++i) {
    Packed p = PackComponent(a[i], lo, hi, scale, offset);
    bits |= (p.bits & 0xFFu) << (8 * i);
    stable = stable && p.stable;
  }
  return PackResult(c, name, bits, stable, {a[0], a[1], a[2], a[3]});
}

// The raw bits of an unpacking instruction's scalar operand; its box, if any, makes every
// bit uncertain.
uint32_t RawBits(const Val& s) { return std::bit_cast<uint32_t>(s.v); }

// An unpacked component `v` of operand `s`: exact for UP2H, one rounding of the division
// for the others (an implementation may multiply by the reciprocal).
Val Unpacked(const Val& s, float v, bool divided) {
  float err = s.err > 0.0f ? kUnstable : 0.0f;
  if (divided && err == 0.0f) err = RoundUp(kRounding * std::fabs(Wide(v)));
  return From(v, {s}, err);
}

// UP2US, UP4B, UP4UB: `count` fields of `width` bits, (field + offset) / divisor each.
Reg UnpackFields(const OpContext& c, int width, int count, float offset, float divisor) {
  const Val s = c.src[0][0];
  const uint32_t bits = RawBits(s);
  const uint32_t mask = (1u << width) - 1u;
  Reg r;
  for (size_t i = 0; i < 4; ++i) {
    const uint32_t shift = static_cast<uint32_t>(width) * static_cast<uint32_t>(i % count);
    const auto field = static_cast<float>((bits >> shift) & mask);
    r[i] = Unpacked(s, (field + offset) / divisor, true);
  }
  return r;
}

// ---- address registers --------------------------------------------------------------------

// The range of address register components (NV_vertex_program2 2.14.3.3-5).
float ClampAddress(float v) { return std::clamp(v, -512.0f, 511.0f); }

// The address vector `fn` (floor, round) of the operand, clamped: a component is unstable
// where its box reaches another integer, undefined for NaN (the clamp's comparisons keep it).
template <typename F>
Reg AddressMap(const OpContext& c, F fn, const char* name) {
  Reg r;
  for (size_t i = 0; i < 4; ++i) {
    const Val& s = c.src[0][i];
    bool stable = !std::isinf(s.err);
    if (stable && s.err > 0.0f) {
      stable = ClampAddress(fn(s.v - s.err)) == ClampAddress(fn(s.v + s.err));
    }
    r[i] = From(ClampAddress(fn(s.v)), {s}, stable ? 0.0f : kUnstable);
    if (std::isnan(s.v) && r[i].why == kDefined) {
      r[i].why = c.Undefined(std::string(name) + " of NaN");
    }
  }
  return r;
}

// For the flow and stack instructions, which the interpreter runs itself.
Reg NotAnOperation(OpContext&) {
  assert(false && "flow instructions are run by the interpreter");
  return {};
}

}  // namespace

// ARA: (x + z, y + w, x + z, y + w) of the address register, clamped.
Reg OpARA(OpContext& c) {
  const Reg& a = c.src[0];
  Reg r;
  for (size_t i = 0; i < 4; ++i) {
    const Val& p = a[i % 2];
    const Val& q = a[i % 2 + 2];
    const bool exact = p.err == 0.0f && q.err == 0.0f;
    r[i] = From(ClampAddress(p.v + q.v), {p, q}, exact ? 0.0f : kUnstable);
  }
  return r;
}

// ARR: round(tmp) per component, ties to the even integer, clamped.
Reg OpARR(OpContext& c) {
  return AddressMap(
      c, [](float x) { return std::nearbyint(x); }, "ARR");
}

Reg OpArlNv(OpContext& c) {
  return AddressMap(
      c, [](float x) { return std::floor(x); }, "ARL");
}

Reg OpBRA(OpContext& c) { return NotAnOperation(c); }
Reg OpBRK(OpContext& c) { return NotAnOperation(c); }
Reg OpCAL(OpContext& c) { return NotAnOperation(c); }

namespace {

// DDX, DDY: the interpreter draws one point per vector, and "the partials resulting from the
// DDX and DDY instructions are ... zero for point-mode polygons" (NV_fragment_program's
// issue on polygon offset). Partials of infinities "may be encoded as large floating-point
// numbers": undefined.
Reg Derivative(OpContext& c, const char* name) {
  Reg r;
  for (size_t i = 0; i < 4; ++i) {
    const Val& a = c.src[0][i];
    r[i] = From(0.0f, {a});
    if (!std::isfinite(a.v) && r[i].why == kDefined) {
      r[i].why = c.Undefined(std::string(name) + " of an infinite or NaN value");
    }
  }
  return r;
}

}  // namespace

Reg OpDDX(OpContext& c) { return Derivative(c, "DDX"); }
Reg OpDDY(OpContext& c) { return Derivative(c, "DDY"); }

// DIV: tmp0 / tmp1 per component (tmp1 a scalar); "may not produce results identical to a
// RCP/MUL sequence": the reciprocal's accuracy.
Reg OpDIV(OpContext& c) {
  const Val s = c.src[1][0];
  Reg r;
  for (size_t i = 0; i < 4; ++i) {
    const Val& a = c.src[0][i];
    const float v = a.v / s.v;
    const float err = ReachesZero(s)
                          ? kUnstable
                          : CornerBound<2>(
                                v, {a, s}, [](const D2& x) { return x[0] / x[1]; }, 0.0, kApprox);
    r[i] = From(v, {a, s}, err);
  }
  return r;
}

// DP2: tmp0.x * tmp1.x + tmp0.y * tmp1.y, replicated: DP3 with z products of -0.
Reg OpDP2(OpContext& c) {
  return RunArb(c, Opcode::DP3, {WithZ(c.src[0], -0.0f), WithZ(c.src[1], 0.0f), Reg{}});
}

// DP2A: tmp0.x * tmp1.x + tmp0.y * tmp1.y + tmp2.x, replicated: DPH with tmp2.x as its w.
Reg OpDP2A(OpContext& c) {
  Reg b = WithZ(c.src[1], 0.0f);
  b[3] = c.src[2][0];
  return RunArb(c, Opcode::DPH, {WithZ(c.src[0], -0.0f), b, Reg{}});
}

Reg OpELSE(OpContext& c) { return NotAnOperation(c); }
Reg OpENDIF(OpContext& c) { return NotAnOperation(c); }
Reg OpENDLOOP(OpContext& c) { return NotAnOperation(c); }
Reg OpENDREP(OpContext& c) { return NotAnOperation(c); }
Reg OpIF(OpContext& c) { return NotAnOperation(c); }
Reg OpLOOP(OpContext& c) { return NotAnOperation(c); }

// NRM: tmp.xyz * ApproxRSQ(tmp.xyz . tmp.xyz); w undefined.
Reg OpNRM(OpContext& c) {
  const Reg& a = c.src[0];
  const Reg dot = RunArb(c, Opcode::DP3, {a, a, Reg{}});
  const Reg scale = RunArb(c, Opcode::RSQ, {dot, Reg{}, Reg{}});
  Reg r = RunArb(c, Opcode::MUL, {a, scale, Reg{}});
  r[3] = Val{0.0f, c.Undefined("NRM w")};
  return r;
}

// PK2H: the fp16 bits of x (low half) and y (high half). A conversion that is not exact may
// take either neighbour, and a NaN's bits are not given: the packed value is unstable.
Reg OpPK2H(OpContext& c) {
  const Reg& a = c.src[0];
  const uint32_t bits = HalfBits(a[0].v) | (static_cast<uint32_t>(HalfBits(a[1].v)) << 16);
  bool stable = true;
  for (size_t i = 0; i < 2; ++i) {
    stable = stable && !std::isnan(a[i].v) && ConvertVal(a[i], Precision::H).err == 0.0f;
  }
  Val r = From(std::bit_cast<float>(bits), {a[0], a[1]}, stable ? 0.0f : kUnstable);
  return Replicate(r);
}

// PK2US: round(65535 * clamp(x, 0, 1)) | round(65535 * clamp(y, 0, 1)) << 16.
Reg OpPK2US(OpContext& c) {
  const Reg& a = c.src[0];
  Packed x = PackComponent(a[0], 0.0, 1.0, 65535.0, 0.0);
  Packed y = PackComponent(a[1], 0.0, 1.0, 65535.0, 0.0);
  return PackResult(c, "PK2US", x.bits | (y.bits << 16), x.stable && y.stable, {a[0], a[1]});
}

// PK4B: round(127 * clamp(v, -128/127, +127/127) + 128) per byte.
Reg OpPK4B(OpContext& c) { return PackBytes(c, "PK4B", Wide(-128.0f / 127.0f), 1.0, 127.0, 128.0); }

// PK4UB: round(255 * clamp(v, 0, 1)) per byte.
Reg OpPK4UB(OpContext& c) { return PackBytes(c, "PK4UB", 0.0, 1.0, 255.0, 0.0); }

Reg OpPOPA(OpContext& c) { return NotAnOperation(c); }
Reg OpPUSHA(OpContext& c) { return NotAnOperation(c); }

namespace {

// RCC: ApproxReciprocal clamped to [2^-64, 2^64] when positive, to [-2^64, -2^-64]
// otherwise; NaN stays NaN, RCC(+0) = 2^64, RCC(-0) = -2^64 (NV_vertex_program2 2.14.3.25).
template <typename T>
T ClampReciprocal(T x) {
  const T r = T{1} / x;
  if (r > 0) return std::clamp(r, T{0x1p-64}, T{0x1p64});
  if (r <= 0) return std::clamp(r, T{-0x1p64}, T{-0x1p-64});
  return r;
}

}  // namespace

Reg OpRCC(OpContext& c) {
  const Val s = c.src[0][0];
  const float v = ClampReciprocal(s.v);
  const float err =
      ReachesZero(s) ? kUnstable
                     : CornerBound<1>(
                           v, {s}, [](const D1& x) { return ClampReciprocal(x[0]); }, 0.0, kApprox);
  return Replicate(From(v, {s}, err));
}

Reg OpREP(OpContext& c) { return NotAnOperation(c); }
Reg OpRET(OpContext& c) { return NotAnOperation(c); }

// RFL: 2 * (axis . dir) / (axis . axis) * axis - dir, xyz; w is not a result (a program
// that writes it fails to load).
Reg OpRFL(OpContext& c) {
  const Reg& axis = c.src[0];
  const Reg& dir = c.src[1];
  const Val w = RunArb(c, Opcode::DP3, {axis, axis, Reg{}})[0];
  const Val d = RunArb(c, Opcode::DP3, {axis, dir, Reg{}})[0];
  const float q = 2.0f * d.v / w.v;
  const float q_err =
      ReachesZero(w) ? kUnstable
                     : CornerBound<2>(
                           q, {d, w}, [](const D2& x) { return 2.0 * x[0] / x[1]; }, 0.0, kApprox);
  const Reg minus_dir{Negated(dir[0]), Negated(dir[1]), Negated(dir[2]), Negated(dir[3])};
  Reg r = RunArb(c, Opcode::MAD, {Replicate(From(q, {d, w}, q_err)), axis, minus_dir});
  r[3] = Val{0.0f, c.Undefined("RFL w")};
  return r;
}

Reg OpSEQ(OpContext& c) {
  return SetOn(
      c, "SEQ", [](auto a, auto b) { return a == b; }, true);
}
Reg OpSFL(OpContext&) { return Replicate(Val{0.0f}); }
Reg OpSGT(OpContext& c) {
  return SetOn(
      c, "SGT", [](auto a, auto b) { return a > b; }, false);
}
Reg OpSLE(OpContext& c) {
  return SetOn(
      c, "SLE", [](auto a, auto b) { return a <= b; }, false);
}
Reg OpSNE(OpContext& c) {
  return SetOn(
      c, "SNE", [](auto a, auto b) { return a != b; }, true);
}

// SSG: SetSign, 1 above 0, 0 for -0 and +0, -1 below, NaN for NaN.
Reg OpSSG(OpContext& c) {
  Reg r;
  for (size_t i = 0; i < 4; ++i) {
    const Val& a = c.src[0][i];
    auto sign = [](auto x) -> decltype(x) { return x > 0 ? 1 : (x < 0 ? -1 : (x == 0 ? 0 : x)); };
    const float v = sign(a.v);
    r[i] = From(v, {a},
                CornerBound<1>(
                    v, {a}, [&](const D1& x) { return sign(x[0]); }, 0.0));
  }
  return r;
}

Reg OpSTR(OpContext&) { return Replicate(Val{1.0f}); }

// TXD and TXL sample tmp.xyz as TEX does: the model's textures have one level and the same
// filter for minification and magnification, so the LOD (the partials of TXD, TXL's w)
// does not change the sample.
Reg OpTXD(OpContext& c) { return Execute(Opcode::TEX, c); }
Reg OpTXL(OpContext& c) { return Execute(Opcode::TEX, c); }

// UP2H: the fp16 values of the low (x, z) and high (y, w) halves of the operand's bits.
Reg OpUP2H(OpContext& c) {
  const Val s = c.src[0][0];
  const uint32_t bits = RawBits(s);
  const Val low = Unpacked(s, HalfValue(static_cast<uint16_t>(bits & 0xFFFFu)), false);
  const Val high = Unpacked(s, HalfValue(static_cast<uint16_t>(bits >> 16)), false);
  return {low, high, low, high};
}

// UP2US: the 16-bit halves / 65535 (x, z low; y, w high).
Reg OpUP2US(OpContext& c) { return UnpackFields(c, 16, 2, 0.0f, 65535.0f); }

// UP4B: (byte - 128) / 127, x from the least significant byte.
Reg OpUP4B(OpContext& c) { return UnpackFields(c, 8, 4, -128.0f, 127.0f); }

// UP4UB: byte / 255, x from the least significant byte.
Reg OpUP4UB(OpContext& c) { return UnpackFields(c, 8, 4, 0.0f, 255.0f); }

// X2D: (tmp0.x + tmp1.x * tmp2.x + tmp1.y * tmp2.y, tmp0.y + tmp1.x * tmp2.z + tmp1.y *
// tmp2.w) in x, z and y, w: two DPH of tmp1.xy with the matrix rows, tmp0 as their w.
Reg OpX2D(OpContext& c) {
  const Reg offset = WithZ(c.src[1], -0.0f);
  const Reg& m = c.src[2];
  const Reg row0{m[0], m[1], Val{0.0f}, c.src[0][0]};
  const Reg row1{m[2], m[3], Val{0.0f}, c.src[0][1]};
  const Val x = RunArb(c, Opcode::DPH, {offset, row0, Reg{}})[0];
  const Val y = RunArb(c, Opcode::DPH, {offset, row1, Reg{}})[0];
  return {x, y, x, y};
}

}  // namespace arbiter::arbvp::exec
