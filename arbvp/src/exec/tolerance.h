// The tolerance model (docs/verify.md): every interpreter value carries a bound `err` on how
// far a conforming implementation's value may be from it, propagated through the program.
//
// - An operation evaluates its real-valued function (in double) at the corners of the box
//   [operand - err, operand + err]. Every operation whose box is not handled specially is
//   monotone in each operand separately (ADD, MUL, MAD, LRP, MIN, MAX, EX2, POW, the LIT
//   clamps, and the steps FLR, SGE, SLT, CMP), so its extremes lie at the corners: a step
//   within its bound of the threshold gets the distance between its outcomes, so either
//   outcome agrees.
// - A result the reference rounded, or computed from inexact operands, may differ by the
//   rounding of another evaluation order or a fused multiply-add: kRounding times the
//   magnitude of the terms. Arithmetic gets it even when exact: compilers reassociate sums
//   and products across instructions (no `precise` in ARB or GLSL 1.10).
// - Approximated operations add what the specs allow them: kApprox relative (RCP, RSQ, EX2,
//   POW) or absolute (LG2, SIN, COS), kRough for EXP.z, LOG.z and LIT.z.
// - A denormal may be flushed to zero: FLT_MIN more.
// - A box that reaches a pole or the edge of a domain, an address or KIL decision within
//   rounding, or float overflow gives +inf: the value is not comparable (unstable).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "exec/machine.h"

namespace arbiter::arbvp::exec {

inline constexpr double kRounding = 0x1p-23;        // one ulp: another order, a fused MAD
inline constexpr double kApprox = 0x1p-16;          // "about 1 part in 10^5" (GL 2.0 2.1.1)
inline constexpr double kRough = 0x1p-11;           // EXP.z, LOG.z, LIT.z (ARBvp issue 28)
inline constexpr double kTexel = 0x1p-8;            // sub-texel precision of a lookup, in texels
inline constexpr double kCoordPrecision = 0x1p-16;  // of a texture coordinate's magnitude
inline constexpr double kDepthPrecision = 0x1p-21;  // window z and depth references
inline constexpr float kUnstable = std::numeric_limits<float>::infinity();

// What the corners of a box told about a float result v.
class Spread {
 public:
  explicit Spread(float v) : v_(v) {}
  // Adds the exact value at one corner (or at the centre).
  void Add(double c) {
    if (std::isnan(v_)) {
      bad_ = bad_ || !std::isnan(c);
    } else if (std::isinf(v_)) {
      bool same = std::signbit(c) == std::signbit(v_) &&
                  std::fabs(c) > Wide(std::numeric_limits<float>::max());
      bad_ = bad_ || !same;
      overflow_ = overflow_ || std::isfinite(c);
    } else if (!std::isfinite(c) || std::fabs(c) > Wide(std::numeric_limits<float>::max())) {
      bad_ = true;
    } else {
      spread_ = std::max(spread_, std::fabs(c - static_cast<double>(v_)));
    }
  }
  void Widen(double e) { spread_ += e; }
  // An operand's magnitude, for the overflow check of a reassociated evaluation.
  void NoteOperand(float x) {
    if (std::isfinite(x)) largest_ = std::max(largest_, std::fabs(Wide(x)));
  }
  void MarkUnstable() { bad_ = true; }
  bool exact() const { return !bad_ && spread_ == 0.0; }
  // The bound: the spread, the rounding of `magnitude` when not exact, the approximation
  // allowance (relative `rel` of |v| plus `abs`), the flush of a denormal, and +inf where
  // the box is unstable or reaches float overflow. Non-finite values are exact or unstable
  // (an overflow of a reformulated one: another order of its terms may stay finite).
  // `reformulated`: implementations evaluate the operation by another formula or order
  // (dot products, LRP as mix), so even an exact result gets the rounding allowance.
  float Bound(double magnitude, double rel = 0.0, double abs = 0.0,
              bool reformulated = false) const;

 private:
  float v_;
  double spread_ = 0.0;
  double largest_ = 0.0;
  bool bad_ = false;
  bool overflow_ = false;  // v is an infinity that finite values overflowed to
};

// The bound of the float result `v` of the real function `f` of `in` (monotone in each
// operand separately), with `magnitude` the size of its terms for the rounding allowance.
template <size_t N, typename F>
float CornerBound(float v, const std::array<Val, N>& in, F f, double magnitude, double rel = 0.0,
                  double abs = 0.0, bool reformulated = false) {
  std::array<double, N> x{};
  for (size_t i = 0; i < N; ++i) {
    if (std::isinf(in[i].err)) return kUnstable;
    x[i] = Wide(in[i].v);
  }
  Spread s(v);
  s.Add(f(x));
  for (const Val& operand : in) s.NoteOperand(operand.v);
  unsigned inexact = 0;  // the operands with a box
  for (size_t i = 0; i < N; ++i) {
    if (in[i].err > 0.0f) inexact |= 1u << i;
  }
  if (inexact != 0) {
    for (unsigned mask = 0; mask < (1u << N); ++mask) {
      if (mask & ~inexact) continue;  // the same corner as mask & inexact
      std::array<double, N> y = x;
      for (size_t i = 0; i < N; ++i) {
        if (inexact & (1u << i)) y[i] += Wide((mask & (1u << i)) ? in[i].err : -in[i].err);
      }
      s.Add(f(y));
    }
  }
  return s.Bound(magnitude, rel, abs, reformulated);
}

// True when [v - err, v + err] reaches 0 (a pole or the edge of a domain) while v is not an
// exact value; an exact 0 is the operation's own business.
inline bool ReachesZero(const Val& a) { return a.err > 0.0f && !(std::fabs(a.v) > a.err); }

// Rounds a double bound up to the next float.
float RoundUp(double e);

}  // namespace arbiter::arbvp::exec
