// One function per ARB opcode, each the pseudo-code of ARBvp 2.14.5 / ARBfp 3.11.5-3.11.6 in
// float32, dispatched through a table expanded from opcodes.def.
//
// Approximated operations (EX2, LG2, POW, RCP, RSQ, SIN, COS, SCS, EXP.z, LOG.z, LIT.z) are
// computed with the correctly rounded (or nearly so) float library function: the value the
// approximation approximates. They are NOT tagged undefined: the specs define them up to an
// accuracy (EXP/LOG: |error| < 2^-11, ARBvp issue 28; the others "about 1 part in 10^5",
// GL 2.0 section 2.1.1, ARBfp issue 1), so a comparison treats them with a tolerance (the
// ToleranceKind of the execution case tables). Only values the specs leave undefined are
// tagged: LG2 of x <= 0, LOG of 0, POW with a negative base or base 0, the sign of
// RCP(-0), SCS.zw and SCS outside [-PI, PI], XPD.w, TXP with q <= 0, and sampling cases.
#include "exec/ops.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "arbiter/arbvp/deviations.h"
#include "exec/ops_nv.h"
#include "exec/sample.h"
#include "exec/tolerance.h"

namespace arbiter::arbvp::exec {
namespace {

// ---- helpers -----------------------------------------------------------------------------

using D3 = std::array<double, 3>;
using D2 = std::array<double, 2>;
using D1 = std::array<double, 1>;

// A component-wise operation: `f` in float32 (the value), `g` the same function of doubles
// (the tolerance model's real function), `magnitude` of the terms for the rounding allowance;
// `arithmetic`: a sum or product that a compiler may reassociate with its neighbours (GLSL
// and ARB programs have no `precise`), so even an exact result gets the allowance.
template <typename F, typename G, typename M>
Reg Map1(const OpContext& c, F f, G g, M magnitude) {
  const Reg& a = c.src[0];
  Reg r;
  for (size_t i = 0; i < 4; ++i) {
    float v = f(a[i].v);
    r[i] = From(v, {a[i]}, CornerBound<1>(v, {a[i]}, g, magnitude(a[i].v, v)));
  }
  return r;
}

template <typename F, typename G, typename M>
Reg Map2(const OpContext& c, F f, G g, M magnitude, bool arithmetic = false) {
  const Reg& a = c.src[0];
  const Reg& b = c.src[1];
  Reg r;
  for (size_t i = 0; i < 4; ++i) {
    float v = f(a[i].v, b[i].v);
    r[i] = From(
        v, {a[i], b[i]},
        CornerBound<2>(v, {a[i], b[i]}, g, magnitude(a[i].v, b[i].v, v), 0.0, 0.0, arithmetic));
  }
  return r;
}

template <typename F, typename G, typename M>
Reg Map3(const OpContext& c, F f, G g, M magnitude, bool arithmetic = false) {
  const Reg& a = c.src[0];
  const Reg& b = c.src[1];
  const Reg& d = c.src[2];
  Reg r;
  for (size_t i = 0; i < 4; ++i) {
    float v = f(a[i].v, b[i].v, d[i].v);
    r[i] = From(v, {a[i], b[i], d[i]},
                CornerBound<3>(v, {a[i], b[i], d[i]}, g, magnitude(a[i].v, b[i].v, d[i].v, v), 0.0,
                               0.0, arithmetic));
  }
  return r;
}

double Abs(float x) { return std::fabs(static_cast<double>(x)); }
// The magnitude of a result alone (a single rounding).
constexpr auto kOwn1 = [](float, float v) { return Abs(v); };
constexpr auto kOwn2 = [](float, float, float v) { return Abs(v); };
constexpr auto kTerms2 = [](float a, float b, float v) { return Abs(a) + Abs(b) + Abs(v); };

Reg Replicate(Val v) { return {v, v, v, v}; }

// The scalar operand: the parser replicates a scalar suffix, so component 0 holds it.
Val Scalar(const OpContext& c, size_t operand = 0) { return c.src[operand][0]; }

// A replicated scalar result that the specs leave undefined when `undefined_if` holds.
Reg ScalarResult(const OpContext& c, float v, Val dep, float err, bool undefined_if,
                 const char* what) {
  if (undefined_if && dep.why == kDefined) return Replicate({v, c.Undefined(what), err, dep.dev});
  return Replicate(From(v, {dep}, err));
}

// MUL rule 2 (ARBvp 2.14.5.19, ARBfp 3.11.5.19): "+/-0.0 * <x> = +/-0.0, at least for all
// <x> that correspond to representable numbers (IEEE "not a number" and "infinity" encodings
// may be exceptions)"; GL 2.0 2.1.1 likewise. So 0 * inf and 0 * NaN may be 0 or NaN: IEEE
// gives NaN, Mesa's GLSL compiler folds a product with a known 0 (a constant, a false SGE) to
// 0. The rule holds for every product of the pseudo-code (MAD's is "subject to the same
// rules", the dot products, DST, XPD, LRP); a result computed through such a product is
// undefined.
bool ZeroTimesNonFinite(float a, float b) {
  return (a == 0.0f && !std::isfinite(b)) || (b == 0.0f && !std::isfinite(a));
}
bool AnyZeroTimesNonFinite(const Val* a, const Val* b, size_t n) {
  for (size_t i = 0; i < n; ++i) {
    if (ZeroTimesNonFinite(a[i].v, b[i].v)) return true;
  }
  return false;
}
Val UndefinedIfZeroProduct(const OpContext& c, bool zero_times_non_finite, Val r) {
  if (zero_times_non_finite && r.why == kDefined) r.why = c.Undefined("0 times an infinity or NaN");
  return r;
}

// A sum of products sum(a[i] * b[i]) + add: each product's box, the sum's rounding in any
// order (n roundings of the terms' magnitude).
float DotBound(float v, const Val* a, const Val* b, size_t n, const Val* add) {
  Spread s(v);
  double center = 0.0;
  double magnitude = 0.0;
  double spread = 0.0;
  if (add) {
    if (std::isinf(add->err)) return kUnstable;
    center = Wide(add->v);
    magnitude = Abs(add->v);
    s.NoteOperand(add->v);
    spread = Wide(add->err);
  }
  for (size_t i = 0; i < n; ++i) {
    if (std::isinf(a[i].err) || std::isinf(b[i].err)) return kUnstable;
    double p = static_cast<double>(a[i].v) * static_cast<double>(b[i].v);
    s.NoteOperand(a[i].v);
    s.NoteOperand(b[i].v);
    center += p;
    magnitude += std::fabs(p);
    if (a[i].err > 0.0f || b[i].err > 0.0f) {
      if (!std::isfinite(p)) s.MarkUnstable();
      double ea = Wide(a[i].err);
      double eb = Wide(b[i].err);
      spread += Abs(a[i].v) * eb + Abs(b[i].v) * ea + ea * eb;  // the box of the product
    }
  }
  s.Add(center);
  s.Widen(spread);
  return s.Bound(magnitude * static_cast<double>(n), 0.0, 0.0, /*reformulated=*/n > 1);
}

// ---- ALU instructions ----------------------------------------------------------------------

// ABS: result = fabs(tmp)
Reg OpABS(OpContext& c) {
  return Map1(
      c, [](float a) { return std::fabs(a); }, [](const D1& x) { return std::fabs(x[0]); }, kOwn1);
}

// ADD: result = tmp0 + tmp1
Reg OpADD(OpContext& c) {
  return Map2(
      c, [](float a, float b) { return a + b; }, [](const D2& x) { return x[0] + x[1]; }, kTerms2,
      /*arithmetic=*/true);
}

// ARL: result = floor(ScalarLoad(op0)), into the address register's x. An address within
// rounding of an integer is unstable: it selects another element.
Reg OpARL(OpContext& c) {
  Val s = Scalar(c);
  float v = std::floor(s.v);
  float err = CornerBound<1>(
      v, {s}, [](const D1& x) { return std::floor(x[0]); }, 0.0);
  Reg r = Replicate(From(v, {s}, err > 0.0f ? kUnstable : 0.0f));
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
    float err = CornerBound<3>(
        chosen.v, {a, c.src[1][i], c.src[2][i]},
        [](const D3& x) { return x[0] < 0.0 ? x[1] : x[2]; }, 0.0);
    r[i] = From(chosen.v, {a, chosen}, err);
  }
  return r;
}

// Sine and cosine: 1-Lipschitz, so the operand's error carries over; the approximation adds
// kApprox, and the reduction of a large angle with a float pi |x| ulps more.
float TrigBound(float v, double exact, Val s) {
  if (std::isinf(s.err)) return kUnstable;
  Spread sp(v);
  sp.Add(exact);
  sp.Widen(std::min(static_cast<double>(s.err), 2.0));
  return sp.Bound(0.0, 0.0, kApprox + Abs(s.v) * 0x1p-22);
}

// COS: ApproxCosine(tmp), any angle.
Reg OpCOS(OpContext& c) {
  Val s = Scalar(c);
  float v = std::cos(s.v);
  return Replicate(From(v, {s}, TrigBound(v, std::cos(static_cast<double>(s.v)), s)));
}

// DP3: tmp0.x*tmp1.x + tmp0.y*tmp1.y + tmp0.z*tmp1.z, replicated.
Reg OpDP3(OpContext& c) {
  const Reg& a = c.src[0];
  const Reg& b = c.src[1];
  float dot = a[0].v * b[0].v + a[1].v * b[1].v + a[2].v * b[2].v;
  return Replicate(UndefinedIfZeroProduct(c, AnyZeroTimesNonFinite(a.data(), b.data(), 3),
                                          From(dot, {a[0], a[1], a[2], b[0], b[1], b[2]},
                                               DotBound(dot, a.data(), b.data(), 3, nullptr))));
}

// DP4: the four-component dot product, replicated.
Reg OpDP4(OpContext& c) {
  const Reg& a = c.src[0];
  const Reg& b = c.src[1];
  float dot = a[0].v * b[0].v + a[1].v * b[1].v + a[2].v * b[2].v + a[3].v * b[3].v;
  return Replicate(
      UndefinedIfZeroProduct(c, AnyZeroTimesNonFinite(a.data(), b.data(), 4),
                             From(dot, {a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]},
                                  DotBound(dot, a.data(), b.data(), 4, nullptr))));
}

// DPH: tmp0.xyz . tmp1.xyz + tmp1.w, replicated.
Reg OpDPH(OpContext& c) {
  const Reg& a = c.src[0];
  const Reg& b = c.src[1];
  float dot = a[0].v * b[0].v + a[1].v * b[1].v + a[2].v * b[2].v + b[3].v;
  return Replicate(UndefinedIfZeroProduct(c, AnyZeroTimesNonFinite(a.data(), b.data(), 3),
                                          From(dot, {a[0], a[1], a[2], b[0], b[1], b[2], b[3]},
                                               DotBound(dot, a.data(), b.data(), 3, &b[3]))));
}

// DST: (1, tmp0.y * tmp1.y, tmp0.z, tmp1.w)
Reg OpDST(OpContext& c) {
  const Reg& a = c.src[0];
  const Reg& b = c.src[1];
  float y = a[1].v * b[1].v;
  return {Val{1.0f},
          UndefinedIfZeroProduct(c, ZeroTimesNonFinite(a[1].v, b[1].v),
                                 From(y, {a[1], b[1]}, DotBound(y, &a[1], &b[1], 1, nullptr))),
          a[2], b[3]};
}

// EX2: Approx2ToX(tmp), replicated.
Reg OpEX2(OpContext& c) {
  Val s = Scalar(c);
  float v = std::exp2(s.v);
  float err = CornerBound<1>(
      v, {s}, [](const D1& x) { return std::exp2(x[0]); }, 0.0, kApprox);
  return Replicate(From(v, {s}, err));
}

// 2^n for an integral float n, exactly (0 below the denormals, inf above FLT_MAX).
float ExactPowerOfTwo(float n) {
  if (std::isnan(n)) return n;
  if (n > 127.0f) return INFINITY;
  if (n < -149.0f) return 0.0f;
  return std::ldexp(1.0f, static_cast<int>(n));
}

// FRC's bound: within one integer step the box's own width; across one, anything in [0, 1).
float FractionBound(float v, Val s) {
  if (std::isinf(s.err)) return kUnstable;
  double lo = std::floor(Wide(s.v) - Wide(s.err));
  double hi = std::floor(Wide(s.v) + Wide(s.err));
  if (lo != hi) return 1.0f;
  return CornerBound<1>(
      v, {s}, [](const D1& x) { return x[0] - std::floor(x[0]); }, Abs(s.v));
}

// EXP (vp): (2^floor(tmp), tmp - floor(tmp), RoughApprox2ToX(tmp), 1)
Reg OpEXP(OpContext& c) {
  Val s = Scalar(c);
  float fl = std::floor(s.v);
  float x = ExactPowerOfTwo(fl);
  float z = std::exp2(s.v);
  float ex = CornerBound<1>(
      x, {s}, [](const D1& t) { return std::exp2(std::floor(t[0])); }, 0.0);
  float ez = CornerBound<1>(
      z, {s}, [](const D1& t) { return std::exp2(t[0]); }, 0.0, kRough);
  return {From(x, {s}, ex), From(s.v - fl, {s}, FractionBound(s.v - fl, s)), From(z, {s}, ez),
          Val{1.0f}};
}

// FLR: floor(tmp)
Reg OpFLR(OpContext& c) {
  return Map1(
      c, [](float a) { return std::floor(a); }, [](const D1& x) { return std::floor(x[0]); },
      kOwn1);
}

// FRC: tmp - floor(tmp)
Reg OpFRC(OpContext& c) {
  Reg r;
  for (size_t i = 0; i < 4; ++i) {
    Val a = c.src[0][i];
    float v = a.v - std::floor(a.v);
    r[i] = From(v, {a}, FractionBound(v, a));
  }
  return r;
}

// KIL: discard when any component is < 0 (NaN compares false and does not kill). A defined
// negative component decides alone; otherwise an undefined component makes the outcome
// undefined (the run goes on with the values it has). A component whose box reaches 0
// makes the outcome unstable.
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
    bool may_flip = std::isinf(v.err) || (v.err > 0.0f && Wide(v.v) - Wide(v.err) < 0.0 &&
                                          Wide(v.v) + Wide(v.err) >= 0.0);
    if (may_flip) c.kill_unstable = true;
    c.kill_dev |= v.dev;
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
  float v = std::log2(s.v);
  float err = ReachesZero(s)
                  ? kUnstable
                  : CornerBound<1>(
                        v, {s}, [](const D1& x) { return std::log2(x[0]); }, 0.0, 0.0, kApprox);
  return ScalarResult(c, v, s, err, s.v <= 0.0f, "LG2 of a value <= 0");
}

// LIT: see ARBvp 2.14.5.13. x, y clamped to >= 0, w to +-(128 - epsilon) (the spec's range
// "(-128, +128) exclusive": epsilon is the step to the largest float below 128);
// z = x > 0 ? RoughApproxPower(y, w) : 0, with 0^0 = 1.
double LitZ(const D3& s) {
  const double limit = Wide(std::nextafter(128.0f, 0.0f));
  double x = std::max(s[0], 0.0);
  double y = std::max(s[1], 0.0);
  double w = std::clamp(s[2], -limit, limit);
  if (!(x > 0.0)) return 0.0;
  return (y == 0.0 && w == 0.0) ? 1.0 : std::pow(y, w);
}

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
  if (a[0].why == kDefined && !(x > 0.0f) && a[0].err == 0.0f) {
    z = Val{0.0f};  // decided by x alone
  } else {
    bool zero_pow_zero = y == 0.0f && w == 0.0f;
    float p = zero_pow_zero ? 1.0f : std::pow(y, w);
    float v = x > 0.0f ? p : 0.0f;
    bool rough = x > 0.0f && !zero_pow_zero;
    float err = CornerBound<3>(v, {a[0], a[1], a[3]}, LitZ, 0.0, rough ? kRough : 0.0);
    z = From(v, {a[0], a[1], a[3]}, err);
    if (x > 0.0f && zero_pow_zero) z.dev |= kDevLitZeroPowZero;
  }
  float ex = CornerBound<1>(
      x, {a[0]}, [](const D1& t) { return std::max(t[0], 0.0); }, 0.0);
  Val y_out = From(x, {a[0]}, ex);
  // Mesa's LIT clamps with max/min and selects with its own comparisons: any NaN operand.
  if (std::isnan(a[0].v) || std::isnan(a[1].v) || std::isnan(a[3].v)) {
    y_out.dev |= kDevNanClamp;
    z.dev |= kDevNanClamp;
  }
  return {Val{1.0f}, y_out, z, Val{1.0f}};
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
  float lz = std::log2(t);
  std::array<float, 3> err{};
  if (ReachesZero(s) || std::isinf(s.err)) {
    err = {kUnstable, kUnstable, kUnstable};
  } else if (s.err > 0.0f) {
    auto exponent = [](double v) { return std::floor(std::log2(std::fabs(v))); };
    double lo = exponent(std::fabs(Wide(s.v)) - Wide(s.err));
    double hi = exponent(std::fabs(Wide(s.v)) + Wide(s.err));
    err[0] = lo == hi ? 0.0f : 1.0f;
    err[1] = lo == hi ? RoundUp(static_cast<double>(s.err) / std::exp2(lo)) : 1.0f;
  }
  err[2] = CornerBound<1>(
      lz, {s}, [](const D1& v) { return std::log2(std::fabs(v[0])); }, 0.0, 0.0, kRough);
  Reg r{From(e, {s}, err[0]), From(m, {s}, err[1]), From(lz, {s}, err[2]), Val{1.0f}};
  if (t == 0.0f && s.why == kDefined) {
    int why = c.Undefined("LOG of 0");
    for (size_t i = 0; i < 3; ++i) r[i].why = why;
  }
  return r;
}

// LRP: tmp0 * tmp1 + (1 - tmp0) * tmp2. Drivers compute mix() as c + a * (b - c): the
// rounding of both forms; with an infinite operand that form gives NaN where the spec's
// gives an infinity (a known deviation).
Reg OpLRP(OpContext& c) {
  Reg r;
  for (size_t i = 0; i < 4; ++i) {
    const Val& a = c.src[0][i];
    const Val& b = c.src[1][i];
    const Val& d = c.src[2][i];
    float v = a.v * b.v + (1.0f - a.v) * d.v;
    double magnitude = Abs(a.v) * Abs(b.v) + std::fabs(1.0 - Wide(a.v)) * Abs(d.v) + Abs(d.v) +
                       Abs(a.v) * std::fabs(Wide(b.v) - Wide(d.v)) + Abs(v);
    float err = CornerBound<3>(
        v, {a, b, d}, [](const D3& t) { return t[0] * t[1] + (1.0 - t[0]) * t[2]; }, magnitude, 0.0,
        0.0, /*reformulated=*/true);
    r[i] = UndefinedIfZeroProduct(
        c, ZeroTimesNonFinite(a.v, b.v) || ZeroTimesNonFinite(1.0f - a.v, d.v),
        From(v, {a, b, d}, err));
    if (std::isinf(a.v) || std::isinf(b.v) || std::isinf(d.v)) r[i].dev |= kDevLrpInfinite;
  }
  return r;
}

// Tags the components of a product's result `r` whose factors are 0 and a non-finite value.
Reg UndefinedIfZeroProducts(const OpContext& c, Reg r) {
  for (size_t i = 0; i < 4; ++i) {
    r[i] = UndefinedIfZeroProduct(c, ZeroTimesNonFinite(c.src[0][i].v, c.src[1][i].v), r[i]);
  }
  return r;
}

// MAD: tmp0 * tmp1 + tmp2
Reg OpMAD(OpContext& c) {
  return UndefinedIfZeroProducts(
      c, Map3(
             c, [](float a, float b, float d) { return a * b + d; },
             [](const D3& x) { return x[0] * x[1] + x[2]; },
             [](float a, float b, float d, float v) { return Abs(a) * Abs(b) + Abs(d) + Abs(v); },
             /*arithmetic=*/true));
}

// MAX and MIN as the specs write them; where that gives NaN from one NaN operand, Mesa's
// maxNum/minNum gives the other operand (a known deviation).
Reg MinMax(OpContext& c, bool max) {
  Reg r = Map2(
      c,
      [max](float a, float b) {
        if (max) return a > b ? a : b;
        return a > b ? b : a;
      },
      [max](const D2& x) {
        if (max) return x[0] > x[1] ? x[0] : x[1];
        return x[0] > x[1] ? x[1] : x[0];
      },
      kOwn2);
  for (size_t i = 0; i < 4; ++i) {
    if (std::isnan(r[i].v) && !(std::isnan(c.src[0][i].v) && std::isnan(c.src[1][i].v))) {
      r[i].dev |= kDevNanClamp;
    }
  }
  return r;
}

// MAX: (tmp0 > tmp1) ? tmp0 : tmp1
Reg OpMAX(OpContext& c) { return MinMax(c, true); }

// MIN: (tmp0 > tmp1) ? tmp1 : tmp0
Reg OpMIN(OpContext& c) { return MinMax(c, false); }

// MOV: result = tmp
Reg OpMOV(OpContext& c) { return c.src[0]; }

// MUL: tmp0 * tmp1
Reg OpMUL(OpContext& c) {
  return UndefinedIfZeroProducts(
      c, Map2(
             c, [](float a, float b) { return a * b; }, [](const D2& x) { return x[0] * x[1]; },
             kOwn2, /*arithmetic=*/true));
}

// POW: ApproxPower(tmp0, tmp1) = ApproxExp2(tmp1 * ApproxLog2(tmp0)), replicated. A negative
// base or base 0 goes through an undefined logarithm (tagged); the value kept for base 0 is
// the formula's limit (0^b = 0 for b > 0, +inf for b < 0, 1 for 0^0), which softpipe gives
// and llvmpipe does not.
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
  float err = 0.0f;
  if (ReachesZero(a) || (a.v == 0.0f && b.err > 0.0f && ReachesZero(b))) {
    err = kUnstable;
  } else if (a.v > 0.0f) {
    err = CornerBound<2>(
        v, {a, b}, [](const D2& x) { return std::pow(x[0], x[1]); }, 0.0, kApprox);
  } else if (a.v == 0.0f) {
    err = std::isinf(b.err) ? kUnstable : 0.0f;
  }
  Val dep = From(v, {a, b}, err);
  if (dep.why == kDefined) {
    if (a.v < 0.0f) return Replicate({v, c.Undefined("POW with a negative base"), err, dep.dev});
    if (a.v == 0.0f) {
      return Replicate(
          {v, c.Undefined("POW with base 0 (ApproxLog2(0) is undefined)"), err, dep.dev});
    }
  }
  return Replicate(dep);
}

// RCP: ApproxReciprocal(tmp), replicated. RCP(-0): the sign of the infinity is undefined
// (drivers give +inf or -inf); RCP(+0) = +inf is the IEEE reciprocal.
Reg OpRCP(OpContext& c) {
  Val s = Scalar(c);
  bool negative_zero = s.v == 0.0f && std::signbit(s.v);
  float v = 1.0f / s.v;
  float err = ReachesZero(s) ? kUnstable
                             : CornerBound<1>(
                                   v, {s}, [](const D1& x) { return 1.0 / x[0]; }, 0.0, kApprox);
  return ScalarResult(c, v, s, err, negative_zero, "RCP of -0 (sign of the infinity)");
}

// RSQ: ApproxRSQRT(fabs(tmp)), replicated (fabs first, so RSQ(-0) = +inf).
Reg OpRSQ(OpContext& c) {
  Val s = Scalar(c);
  float v = 1.0f / std::sqrt(std::fabs(s.v));
  float err =
      ReachesZero(s)
          ? kUnstable
          : CornerBound<1>(
                v, {s}, [](const D1& x) { return 1.0 / std::sqrt(std::fabs(x[0])); }, 0.0, kApprox);
  return Replicate(From(v, {s}, err));
}

// SCS: (ApproxCosine(tmp), ApproxSine(tmp), undefined, undefined); the whole result is
// undefined outside [-PI, PI].
Reg OpSCS(OpContext& c) {
  Val s = Scalar(c);
  float cv = std::cos(s.v);
  float sv = std::sin(s.v);
  Reg r{From(cv, {s}, TrigBound(cv, std::cos(static_cast<double>(s.v)), s)),
        From(sv, {s}, TrigBound(sv, std::sin(static_cast<double>(s.v)), s)), Val{0.0f}, Val{1.0f}};
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

// SGE and SLT compare as the pseudo-code does: a NaN operand makes the comparison false, 0.
// Mesa's GLSL path may fold such a comparison with another one (a known deviation).
Reg NanComparesFalse(const OpContext& c, Reg r) {
  for (size_t i = 0; i < 4; ++i) {
    if (std::isnan(c.src[0][i].v) || std::isnan(c.src[1][i].v)) r[i].dev |= kDevNanCompareFolded;
  }
  return r;
}

// SGE: tmp0 >= tmp1 ? 1 : 0
Reg OpSGE(OpContext& c) {
  return NanComparesFalse(c, Map2(
                                 c, [](float a, float b) { return a >= b ? 1.0f : 0.0f; },
                                 [](const D2& x) { return x[0] >= x[1] ? 1.0 : 0.0; }, kOwn2));
}

// SIN: ApproxSine(tmp), any angle.
Reg OpSIN(OpContext& c) {
  Val s = Scalar(c);
  float v = std::sin(s.v);
  return Replicate(From(v, {s}, TrigBound(v, std::sin(static_cast<double>(s.v)), s)));
}

// SLT: tmp0 < tmp1 ? 1 : 0
Reg OpSLT(OpContext& c) {
  return NanComparesFalse(c, Map2(
                                 c, [](float a, float b) { return a < b ? 1.0f : 0.0f; },
                                 [](const D2& x) { return x[0] < x[1] ? 1.0 : 0.0; }, kOwn2));
}

// SUB: tmp0 - tmp1
Reg OpSUB(OpContext& c) {
  return Map2(
      c, [](float a, float b) { return a - b; }, [](const D2& x) { return x[0] - x[1]; }, kTerms2,
      /*arithmetic=*/true);
}

// SWZ: the extended swizzle (selection, 0, 1 and per-component negation) is applied when
// the operand is loaded; the result is the loaded vector.
Reg OpSWZ(OpContext& c) { return c.src[0]; }

// XPD: the cross product of tmp0.xyz and tmp1.xyz; w undefined.
Val CrossComponent(const OpContext& c, size_t i, size_t j) {
  const Reg& a = c.src[0];
  const Reg& b = c.src[1];
  float v = a[i].v * b[j].v - a[j].v * b[i].v;
  std::array<Val, 2> left{a[i], a[j]};
  Val nb = b[i];
  nb.v = -nb.v;
  std::array<Val, 2> right{b[j], nb};
  return UndefinedIfZeroProduct(
      c, ZeroTimesNonFinite(a[i].v, b[j].v) || ZeroTimesNonFinite(a[j].v, b[i].v),
      From(v, {a[i], a[j], b[i], b[j]}, DotBound(v, left.data(), right.data(), 2, nullptr)));
}

Reg OpXPD(OpContext& c) {
  return {CrossComponent(c, 1, 2), CrossComponent(c, 2, 0), CrossComponent(c, 0, 1),
          Val{0.0f, c.Undefined("XPD w")}};
}

// ---- texture instructions ------------------------------------------------------------------

// The coordinate components a target reads: s (1D), s t (2D, RECT), s t r (3D, CUBE,
// SHADOW2D, SHADOWRECT), s r (SHADOW1D) (texture_targets.def).
std::array<bool, 3> UsedCoords(TexTarget target) {
  const uint8_t mask = TexTargetCoordMask(target);
  return {(mask & 1u) != 0, (mask & 2u) != 0, (mask & 4u) != 0};
}

// How far a lookup may move each coordinate: its own error, kTexel of a texel and
// kCoordPrecision of its magnitude (in the coordinate's units), or the depth precision for
// the reference of a depth comparison. False when the lookup is unstable: a box wider than a
// texel, a repeated or mirrored coordinate within rounding of an integer (where drivers'
// fractions round to either end), or a cube direction whose major axis has a denormal
// reciprocal.
bool LookupBox(const OpContext& c, const std::array<Val, 3>& coord, std::array<double, 3>* box) {
  *box = {};
  auto it = c.textures->find(c.inst->tex_unit);
  if (it == c.textures->end()) return true;
  const Texture& tex = it->second;
  const TexTarget target = c.inst->target;
  const bool shadow = IsShadowTarget(target);
  const std::array<int, 3> size{tex.width, tex.height, tex.depth};
  const std::array<bool, 3> used = UsedCoords(target);
  double major = std::max({Abs(coord[0].v), Abs(coord[1].v), Abs(coord[2].v)});
  if (tex.dim == TexDim::Cube && major > 0x1p126) return false;
  for (size_t i = 0; i < 3; ++i) {
    if (!used[i]) continue;
    if (shadow && i == 2) {
      (*box)[i] = Wide(coord[i].err) + kDepthPrecision;
      continue;
    }
    double texel = 1.0 / size[i];
    if (tex.dim == TexDim::Rect) texel = 1.0;
    if (tex.dim == TexDim::Cube) texel = 2.0 * major / tex.width;
    double b = Wide(coord[i].err) + kTexel * texel + Abs(coord[i].v) * kCoordPrecision;
    (*box)[i] = b;
    if (!(b <= texel)) return false;
    bool wraps =
        tex.dim != TexDim::Rect && tex.dim != TexDim::Cube && tex.wrap != TexWrap::ClampToEdge;
    double s = Wide(coord[i].v);
    if (wraps && std::floor(s - b) != std::floor(s + b) && s != std::round(s)) return false;
  }
  return true;
}

// TextureSample(s, t, r, bias, unit, target) at coordinate `coord` (projected for TXP; q
// was a dependency then). The tolerance: the largest change of each channel over the
// corners of the lookup box.
Reg SampleAt(OpContext& c, const std::array<Val, 3>& coord, Val q, bool projected) {
  const Instruction& inst = *c.inst;
  Sample sample = SampleTexture(*c.textures, inst.tex_unit, inst.target, coord[0].v, coord[1].v,
                                coord[2].v, c.shadow_option);
  std::array<bool, 3> used = UsedCoords(inst.target);
  int why = kDefined;
  uint32_t dev = q.dev;
  bool unstable = projected && std::isinf(q.err);
  for (size_t i = 0; i < 3; ++i) {
    if (!used[i]) continue;
    if (why == kDefined && coord[i].why != kDefined) why = coord[i].why;
    dev |= coord[i].dev;
    unstable = unstable || std::isinf(coord[i].err);
  }
  if (why == kDefined && projected && q.why != kDefined) why = q.why;
  if (why == kDefined && projected && q.v <= 0.0f) why = c.Undefined("TXP with q <= 0");
  if (why == kDefined && !sample.undefined.empty()) why = c.Undefined(sample.undefined);
  Reg r = UndefinedReg(sample.value, why);
  if (sample.cube_edge) dev |= kDevCubeEdgeLlvmpipe;
  if (sample.mirror_centre) dev |= kDevMirrorCentreSoftpipe;
  std::array<double, 4> spread{};
  std::array<double, 3> box{};
  if (!unstable && why == kDefined && !LookupBox(c, coord, &box)) unstable = true;
  if (!unstable) {
    for (unsigned mask = 0; mask < 8; ++mask) {
      std::array<float, 3> at{};
      bool skip = false;
      for (size_t i = 0; i < 3; ++i) {
        skip = skip || (!used[i] && (mask & (1u << i)));
        double d = used[i] ? ((mask & (1u << i)) ? box[i] : -box[i]) : 0.0;
        at[i] = static_cast<float>(Wide(coord[i].v) + d);
      }
      if (skip) continue;
      Sample corner_sample = SampleTexture(*c.textures, inst.tex_unit, inst.target, at[0], at[1],
                                           at[2], c.shadow_option);
      if (corner_sample.cube_edge) dev |= kDevCubeEdgeLlvmpipe;
      const Vec4& corner = corner_sample.value;
      for (size_t k = 0; k < 4; ++k) {
        double delta = std::fabs(Wide(corner[k]) - Wide(sample.value[k]));
        spread[k] = std::isnan(delta) ? HUGE_VAL : std::max(spread[k], delta);
      }
    }
  }
  for (size_t k = 0; k < 4; ++k) {
    r[k].err = unstable ? kUnstable : RoundUp(spread[k]);
    r[k].dev = dev;
  }
  return r;
}

// TEX: TextureSample(tmp.x, tmp.y, tmp.z, 0)
Reg OpTEX(OpContext& c) {
  const Reg& a = c.src[0];
  return SampleAt(c, {a[0], a[1], a[2]}, Val{1.0f}, false);
}

// TXP: TextureSample(tmp.x / tmp.w, tmp.y / tmp.w, tmp.z / tmp.w, 0); undefined for w <= 0.
Reg OpTXP(OpContext& c) {
  const Reg& a = c.src[0];
  Val q = a[3];
  std::array<Val, 3> coord;
  for (size_t i = 0; i < 3; ++i) {
    float v = a[i].v / q.v;
    float err = ReachesZero(q) ? kUnstable
                               : CornerBound<2>(
                                     v, {a[i], q}, [](const D2& x) { return x[0] / x[1]; }, 0.0);
    coord[i] = Val{v, a[i].why, err, a[i].dev};
  }
  return SampleAt(c, coord, q, true);
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
#define ARBVP_OPCODE(name, vp, fp, signature, klass, vp_mods, fp_mods, fp2_mods, reads, spec) \
  &Op##name,
#include "arbiter/arbvp/opcodes.def"
#undef ARBVP_OPCODE
};

}  // namespace

Reg Execute(Opcode op, OpContext& ctx) { return kOps[static_cast<size_t>(op)](ctx); }

}  // namespace arbiter::arbvp::exec
