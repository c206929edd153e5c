// One function per ARB opcode, each the pseudo-code of ARBvp 2.14.5 / ARBfp 3.11.5-3.11.6 in
// float32, dispatched through a table expanded from opcodes.def.
//
// Approximated operations (EX2, LG2, POW, RCP, RSQ, SIN, COS, SCS, EXP.z, LOG.z, LIT.z) are
// computed with the correctly rounded (or nearly so) float library function: the value the
// approximation approximates. They are NOT tagged undefined: the specs define them up to an
// accuracy (EXP/LOG: |error| < 2^-11, ARBvp issue 28; the others "about 1 part in 10^5",
// GL 2.0 section 2.1.1, ARBfp issue 1), so a comparison treats them with a tolerance (the
// ToleranceKind of the execution case tables). Only values the specs leave undefined are
// tagged: LG2 of x <= 0, LOG of 0, POW with a negative base and POW(0, 0), the sign of
// RCP(-0), SCS.zw and SCS outside [-PI, PI], XPD.w, TXP with q <= 0, and sampling cases.
#include "exec/ops.h"

#include <cmath>
#include <numbers>

#include "exec/sample.h"

namespace arbiter::arbvp::exec {
namespace {

// ---- helpers -----------------------------------------------------------------------------

template <typename F>
Reg Map1(const OpContext& c, F f) {
  const Reg& a = c.src[0];
  Reg r;
  for (size_t i = 0; i < 4; ++i) r[i] = From(f(a[i].v), {a[i]});
  return r;
}

template <typename F>
Reg Map2(const OpContext& c, F f) {
  const Reg& a = c.src[0];
  const Reg& b = c.src[1];
  Reg r;
  for (size_t i = 0; i < 4; ++i) r[i] = From(f(a[i].v, b[i].v), {a[i], b[i]});
  return r;
}

template <typename F>
Reg Map3(const OpContext& c, F f) {
  const Reg& a = c.src[0];
  const Reg& b = c.src[1];
  const Reg& d = c.src[2];
  Reg r;
  for (size_t i = 0; i < 4; ++i) r[i] = From(f(a[i].v, b[i].v, d[i].v), {a[i], b[i], d[i]});
  return r;
}

Reg Replicate(Val v) { return {v, v, v, v}; }

// The scalar operand: the parser replicates a scalar suffix, so component 0 holds it.
Val Scalar(const OpContext& c, size_t operand = 0) { return c.src[operand][0]; }

// A replicated scalar result that the specs leave undefined when `undefined_if` holds.
Reg ScalarResult(const OpContext& c, float v, Val dep, bool undefined_if, const char* what) {
  if (undefined_if && dep.why == kDefined) return Replicate({v, c.Undefined(what)});
  return Replicate(From(v, {dep}));
}

// ---- ALU instructions ----------------------------------------------------------------------

// ABS: result = fabs(tmp)
Reg OpABS(OpContext& c) {
  return Map1(c, [](float a) { return std::fabs(a); });
}

// ADD: result = tmp0 + tmp1
Reg OpADD(OpContext& c) {
  return Map2(c, [](float a, float b) { return a + b; });
}

// ARL: result = floor(ScalarLoad(op0)), into the address register's x.
Reg OpARL(OpContext& c) {
  Val s = Scalar(c);
  Reg r = Replicate(From(std::floor(s.v), {s}));
  if (!std::isfinite(s.v) && s.why == kDefined) {
    r[0].why = c.Undefined("ARL of an infinite or NaN value");
  }
  return r;
}

// CMP: result = tmp0 < 0 ? tmp1 : tmp2 (only the selected operand matters)
Reg OpCMP(OpContext& c) {
  Reg r;
  for (size_t i = 0; i < 4; ++i) {
    Val a = c.src[0][i];
    Val chosen = a.v < 0.0f ? c.src[1][i] : c.src[2][i];
    r[i] = From(chosen.v, {a, chosen});
  }
  return r;
}

// COS: ApproxCosine(tmp), any angle.
Reg OpCOS(OpContext& c) {
  Val s = Scalar(c);
  return Replicate(From(std::cos(s.v), {s}));
}

// DP3: tmp0.x*tmp1.x + tmp0.y*tmp1.y + tmp0.z*tmp1.z, replicated.
Reg OpDP3(OpContext& c) {
  const Reg& a = c.src[0];
  const Reg& b = c.src[1];
  float dot = a[0].v * b[0].v + a[1].v * b[1].v + a[2].v * b[2].v;
  return Replicate(From(dot, {a[0], a[1], a[2], b[0], b[1], b[2]}));
}

// DP4: the four-component dot product, replicated.
Reg OpDP4(OpContext& c) {
  const Reg& a = c.src[0];
  const Reg& b = c.src[1];
  float dot = a[0].v * b[0].v + a[1].v * b[1].v + a[2].v * b[2].v + a[3].v * b[3].v;
  return Replicate(From(dot, {a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]}));
}

// DPH: tmp0.xyz . tmp1.xyz + tmp1.w, replicated.
Reg OpDPH(OpContext& c) {
  const Reg& a = c.src[0];
  const Reg& b = c.src[1];
  float dot = a[0].v * b[0].v + a[1].v * b[1].v + a[2].v * b[2].v + b[3].v;
  return Replicate(From(dot, {a[0], a[1], a[2], b[0], b[1], b[2], b[3]}));
}

// DST: (1, tmp0.y * tmp1.y, tmp0.z, tmp1.w)
Reg OpDST(OpContext& c) {
  const Reg& a = c.src[0];
  const Reg& b = c.src[1];
  return {Val{1.0f}, From(a[1].v * b[1].v, {a[1], b[1]}), a[2], b[3]};
}

// EX2: Approx2ToX(tmp), replicated.
Reg OpEX2(OpContext& c) {
  Val s = Scalar(c);
  return Replicate(From(std::exp2(s.v), {s}));
}

// 2^n for an integral float n, exactly (0 below the denormals, inf above FLT_MAX).
float ExactPowerOfTwo(float n) {
  if (std::isnan(n)) return n;
  if (n > 127.0f) return INFINITY;
  if (n < -149.0f) return 0.0f;
  return std::ldexp(1.0f, static_cast<int>(n));
}

// EXP (vp): (2^floor(tmp), tmp - floor(tmp), RoughApprox2ToX(tmp), 1)
Reg OpEXP(OpContext& c) {
  Val s = Scalar(c);
  float fl = std::floor(s.v);
  return {From(ExactPowerOfTwo(fl), {s}), From(s.v - fl, {s}), From(std::exp2(s.v), {s}),
          Val{1.0f}};
}

// FLR: floor(tmp)
Reg OpFLR(OpContext& c) {
  return Map1(c, [](float a) { return std::floor(a); });
}

// FRC: tmp - floor(tmp)
Reg OpFRC(OpContext& c) {
  return Map1(c, [](float a) { return a - std::floor(a); });
}

// KIL: discard when any component is < 0 (NaN compares false and does not kill). A defined
// negative component decides alone; otherwise an undefined component makes the outcome
// undefined (the run goes on with the values it has).
Reg OpKIL(OpContext& c) {
  bool defined_kill = false;
  int undefined_why = kDefined;
  for (const Val& v : c.src[0]) {
    if (v.v < 0.0f) c.killed = true;
    if (v.why == kDefined) {
      defined_kill = defined_kill || v.v < 0.0f;
    } else if (undefined_why == kDefined) {
      undefined_why = v.why;
    }
  }
  if (defined_kill) c.killed_defined = true;
  if (!defined_kill && undefined_why != kDefined && c.kill_why == kDefined) {
    c.kill_why = undefined_why;
  }
  return {};
}

// LG2: ApproxLog2(tmp), replicated; undefined for tmp <= 0.
Reg OpLG2(OpContext& c) {
  Val s = Scalar(c);
  return ScalarResult(c, std::log2(s.v), s, s.v <= 0.0f, "LG2 of a value <= 0");
}

// LIT: see ARBvp 2.14.5.13. x, y clamped to >= 0, w to +-(128 - epsilon) (the spec's range
// "(-128, +128) exclusive": epsilon is the step to the largest float below 128);
// z = x > 0 ? RoughApproxPower(y, w) : 0, with 0^0 = 1.
Reg OpLIT(OpContext& c) {
  const Reg& a = c.src[0];
  float x = a[0].v < 0.0f ? 0.0f : a[0].v;
  float y = a[1].v < 0.0f ? 0.0f : a[1].v;
  const float limit = std::nextafter(128.0f, 0.0f);
  float w = a[3].v;
  if (w < -limit) {
    w = -limit;
  } else if (w > limit) {
    w = limit;
  }
  Val z;
  if (a[0].why == kDefined && !(x > 0.0f)) {
    z = Val{0.0f};  // decided by x alone
  } else {
    float p = (y == 0.0f && w == 0.0f) ? 1.0f : std::pow(y, w);
    z = From(x > 0.0f ? p : 0.0f, {a[0], a[1], a[3]});
  }
  return {Val{1.0f}, From(x, {a[0]}), z, Val{1.0f}};
}

// LOG (vp): (floor(log2|tmp|), |tmp| / 2^floor(log2|tmp|), RoughApproxLog2(|tmp|), 1).
// floor(log2) and the mantissa come exactly from frexp.
Reg OpLOG(OpContext& c) {
  Val s = Scalar(c);
  float t = std::fabs(s.v);
  float e = 0.0f;
  float m = 0.0f;
  if (t == 0.0f) {
    e = -INFINITY;
    m = NAN;
  } else if (std::isinf(t) || std::isnan(t)) {
    e = t;
    m = t / t;  // inf / inf: NaN, as the pseudo-code's inf / 2^inf
  } else {
    int exp = 0;
    float mant = std::frexp(t, &exp);  // t = mant * 2^exp, mant in [0.5, 1)
    e = static_cast<float>(exp - 1);
    m = mant * 2.0f;
  }
  Reg r{From(e, {s}), From(m, {s}), From(std::log2(t), {s}), Val{1.0f}};
  if (t == 0.0f && s.why == kDefined) {
    int why = c.Undefined("LOG of 0");
    for (size_t i = 0; i < 3; ++i) r[i].why = why;
  }
  return r;
}

// LRP: tmp0 * tmp1 + (1 - tmp0) * tmp2
Reg OpLRP(OpContext& c) {
  return Map3(c, [](float a, float b, float d) { return a * b + (1.0f - a) * d; });
}

// MAD: tmp0 * tmp1 + tmp2
Reg OpMAD(OpContext& c) {
  return Map3(c, [](float a, float b, float d) { return a * b + d; });
}

// MAX: (tmp0 > tmp1) ? tmp0 : tmp1
Reg OpMAX(OpContext& c) {
  return Map2(c, [](float a, float b) { return a > b ? a : b; });
}

// MIN: (tmp0 > tmp1) ? tmp1 : tmp0
Reg OpMIN(OpContext& c) {
  return Map2(c, [](float a, float b) { return a > b ? b : a; });
}

// MOV: result = tmp
Reg OpMOV(OpContext& c) { return c.src[0]; }

// MUL: tmp0 * tmp1
Reg OpMUL(OpContext& c) {
  return Map2(c, [](float a, float b) { return a * b; });
}

// POW: ApproxPower(tmp0, tmp1) = ApproxExp2(tmp1 * ApproxLog2(tmp0)), replicated. A negative
// base goes through the logarithm (undefined); so does 0^0 (0 * log2(0)). Base 0 otherwise:
// 0^b = 0 for b > 0 and +inf for b < 0, the limit of the formula.
Reg OpPOW(OpContext& c) {
  Val a = Scalar(c, 0);
  Val b = Scalar(c, 1);
  float v = 0.0f;
  if (a.v == 0.0f) {
    v = b.v > 0.0f ? 0.0f : (b.v < 0.0f ? INFINITY : (b.v == 0.0f ? 1.0f : NAN));
  } else if (a.v < 0.0f) {
    v = std::exp2(b.v * std::log2(a.v));  // NaN: the formula's value
  } else {
    v = std::pow(a.v, b.v);
  }
  Val dep = From(v, {a, b});
  if (dep.why == kDefined) {
    if (a.v < 0.0f) return Replicate({v, c.Undefined("POW with a negative base")});
    if (a.v == 0.0f && b.v == 0.0f) return Replicate({v, c.Undefined("POW(0, 0)")});
  }
  return Replicate(dep);
}

// RCP: ApproxReciprocal(tmp), replicated. RCP(-0): the sign of the infinity is undefined
// (drivers give +inf or -inf); RCP(+0) = +inf is the IEEE reciprocal.
Reg OpRCP(OpContext& c) {
  Val s = Scalar(c);
  bool negative_zero = s.v == 0.0f && std::signbit(s.v);
  return ScalarResult(c, 1.0f / s.v, s, negative_zero, "RCP of -0 (sign of the infinity)");
}

// RSQ: ApproxRSQRT(fabs(tmp)), replicated (fabs first, so RSQ(-0) = +inf).
Reg OpRSQ(OpContext& c) {
  Val s = Scalar(c);
  return Replicate(From(1.0f / std::sqrt(std::fabs(s.v)), {s}));
}

// SCS: (ApproxCosine(tmp), ApproxSine(tmp), undefined, undefined); the whole result is
// undefined outside [-PI, PI].
Reg OpSCS(OpContext& c) {
  Val s = Scalar(c);
  Reg r{From(std::cos(s.v), {s}), From(std::sin(s.v), {s}), Val{0.0f}, Val{1.0f}};
  int zw = c.Undefined("SCS z and w");
  r[2].why = zw;
  r[3].why = zw;
  if (s.why == kDefined && !(std::fabs(s.v) <= std::numbers::pi_v<float>)) {
    int why = c.Undefined("SCS of an angle outside [-PI, PI]");
    r[0].why = why;
    r[1].why = why;
  }
  return r;
}

// SGE: tmp0 >= tmp1 ? 1 : 0
Reg OpSGE(OpContext& c) {
  return Map2(c, [](float a, float b) { return a >= b ? 1.0f : 0.0f; });
}

// SIN: ApproxSine(tmp), any angle.
Reg OpSIN(OpContext& c) {
  Val s = Scalar(c);
  return Replicate(From(std::sin(s.v), {s}));
}

// SLT: tmp0 < tmp1 ? 1 : 0
Reg OpSLT(OpContext& c) {
  return Map2(c, [](float a, float b) { return a < b ? 1.0f : 0.0f; });
}

// SUB: tmp0 - tmp1
Reg OpSUB(OpContext& c) {
  return Map2(c, [](float a, float b) { return a - b; });
}

// SWZ: the extended swizzle (selection, 0, 1 and per-component negation) is applied when
// the operand is loaded; the result is the loaded vector.
Reg OpSWZ(OpContext& c) { return c.src[0]; }

// XPD: the cross product of tmp0.xyz and tmp1.xyz; w undefined.
Reg OpXPD(OpContext& c) {
  const Reg& a = c.src[0];
  const Reg& b = c.src[1];
  return {From(a[1].v * b[2].v - a[2].v * b[1].v, {a[1], a[2], b[1], b[2]}),
          From(a[2].v * b[0].v - a[0].v * b[2].v, {a[0], a[2], b[0], b[2]}),
          From(a[0].v * b[1].v - a[1].v * b[0].v, {a[0], a[1], b[0], b[1]}),
          Val{0.0f, c.Undefined("XPD w")}};
}

// ---- texture instructions ------------------------------------------------------------------

// The coordinate components a target reads: s (1D), s t (2D, RECT), s t r (3D, CUBE,
// SHADOW2D, SHADOWRECT), s r (SHADOW1D).
std::array<bool, 3> UsedCoords(TexTarget target) {
  switch (target) {
    case TexTarget::Tex1D:
      return {true, false, false};
    case TexTarget::Tex2D:
    case TexTarget::Rect:
      return {true, true, false};
    case TexTarget::Shadow1D:
      return {true, false, true};
    case TexTarget::Tex3D:
    case TexTarget::Cube:
    case TexTarget::Shadow2D:
    case TexTarget::ShadowRect:
      return {true, true, true};
  }
  return {true, true, true};
}

// TextureSample(s, t, r, bias, unit, target) at coordinate `coord` (projected for TXP; q
// was a dependency then).
Reg SampleAt(OpContext& c, const std::array<Val, 3>& coord, Val q, bool projected) {
  const Instruction& inst = *c.inst;
  Sample sample = SampleTexture(*c.textures, inst.tex_unit, inst.target, coord[0].v, coord[1].v,
                                coord[2].v, c.shadow_option);
  std::array<bool, 3> used = UsedCoords(inst.target);
  int why = kDefined;
  for (size_t i = 0; i < 3 && why == kDefined; ++i) {
    if (used[i] && coord[i].why != kDefined) why = coord[i].why;
  }
  if (why == kDefined && projected && q.why != kDefined) why = q.why;
  if (why == kDefined && projected && q.v <= 0.0f) why = c.Undefined("TXP with q <= 0");
  if (why == kDefined && !sample.undefined.empty()) why = c.Undefined(sample.undefined);
  return UndefinedReg(sample.value, why);
}

// TEX: TextureSample(tmp.x, tmp.y, tmp.z, 0)
Reg OpTEX(OpContext& c) {
  const Reg& a = c.src[0];
  return SampleAt(c, {a[0], a[1], a[2]}, Val{1.0f}, false);
}

// TXP: TextureSample(tmp.x / tmp.w, tmp.y / tmp.w, tmp.z / tmp.w, 0); undefined for w <= 0.
Reg OpTXP(OpContext& c) {
  const Reg& a = c.src[0];
  float q = a[3].v;
  return SampleAt(c,
                  {Val{a[0].v / q, a[0].why}, Val{a[1].v / q, a[1].why}, Val{a[2].v / q, a[2].why}},
                  a[3], true);
}

// TXB: TextureSample(tmp.x, tmp.y, tmp.z, tmp.w); the model's single level makes the bias
// irrelevant, so tmp.w is no dependency.
Reg OpTXB(OpContext& c) {
  const Reg& a = c.src[0];
  return SampleAt(c, {a[0], a[1], a[2]}, Val{1.0f}, false);
}

using OpFn = Reg (*)(OpContext&);

// Indexed by Opcode: one row per opcodes.def row, in its order.
constexpr OpFn kOps[] = {
#define ARBVP_OPCODE(name, stages, signature, klass, spec) &Op##name,
#include "arbiter/arbvp/opcodes.def"
#undef ARBVP_OPCODE
};

}  // namespace

Reg Execute(Opcode op, OpContext& ctx) { return kOps[static_cast<size_t>(op)](ctx); }

}  // namespace arbiter::arbvp::exec
