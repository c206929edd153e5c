// fp16 and fx12 conversions (precision.h), as NV_fragment_program 3.11.4.2 states them.
#include "exec/precision.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "exec/ops.h"
#include "exec/tolerance.h"

namespace arbiter::arbvp::exec {
namespace {

constexpr uint32_t kHalfOverflow = 0x477FF000u;   // 65520: rounds to +INF (ties to even)
constexpr uint32_t kHalfMinNormal = 0x38800000u;  // 2^-14
constexpr float kLargestHalf = 65504.0f;
constexpr float kFixedMin = -2048.0f / 1024.0f;
constexpr float kFixedMax = 2047.0f / 1024.0f;

// The fp16 step at magnitude m (the denormal step 2^-24 below 2^-14).
double HalfStep(double m) {
  int e = 0;
  std::frexp(m, &e);
  return std::ldexp(1.0, std::max(e - 1, -14) - 10);
}

}  // namespace

uint16_t HalfBits(float x) {
  const uint32_t f = std::bit_cast<uint32_t>(x);
  const auto sign = static_cast<uint16_t>((f >> 16) & 0x8000u);
  const uint32_t magnitude = f & 0x7FFFFFFFu;
  if (magnitude > 0x7F800000u) return static_cast<uint16_t>(sign | 0x7E00u);
  if (magnitude >= kHalfOverflow) return static_cast<uint16_t>(sign | 0x7C00u);
  if (magnitude < kHalfMinNormal) {
    // A denormal (or 0): a multiple of 2^-24, rounded to nearest even.
    const float scaled = std::bit_cast<float>(magnitude) * 0x1p24f;
    return static_cast<uint16_t>(sign | static_cast<uint16_t>(std::nearbyint(scaled)));
  }
  const uint32_t mantissa = magnitude & 0x7FFFFFu;
  const uint32_t exponent = (magnitude >> 23) - 127u + 15u;
  uint32_t h = (exponent << 10) | (mantissa >> 13);
  const uint32_t rest = mantissa & 0x1FFFu;
  if (rest > 0x1000u || (rest == 0x1000u && (h & 1u))) ++h;  // a carry bumps the exponent
  return static_cast<uint16_t>(sign | h);
}

float HalfValue(uint16_t bits) {
  const uint32_t exponent = (bits >> 10) & 0x1Fu;
  const auto mantissa = static_cast<int>(bits & 0x3FFu);
  float v = 0.0f;
  if (exponent == 0) {
    v = std::ldexp(static_cast<float>(mantissa), -24);
  } else if (exponent == 31) {
    v = mantissa != 0 ? std::numeric_limits<float>::quiet_NaN()
                      : std::numeric_limits<float>::infinity();
  } else {
    v = std::ldexp(static_cast<float>(mantissa | 0x400), static_cast<int>(exponent) - 25);
  }
  return (bits & 0x8000u) ? -v : v;
}

float ToHalf(float x) { return HalfValue(HalfBits(x)); }

float ToFixed(float x) {
  if (std::isnan(x)) return 0.0f;
  const float steps = std::nearbyint(std::clamp(x, -4.0f, 4.0f) * 1024.0f);
  return std::clamp(steps / 1024.0f, kFixedMin, kFixedMax);
}

Val ConvertVal(const Val& v, Precision precision) {
  if (precision != Precision::H && precision != Precision::X) return v;
  const bool half = precision == Precision::H;
  Val r = v;
  r.v = half ? ToHalf(v.v) : ToFixed(v.v);
  if (std::isinf(v.err)) return r;
  const bool exact = v.err == 0.0f && (r.v == v.v || (std::isnan(r.v) && std::isnan(v.v)));
  if (exact) return r;
  if (std::isnan(v.v)) {
    r.err = kUnstable;
    return r;
  }
  const double top = std::fabs(Wide(v.v)) + Wide(v.err);
  if (half) {
    // At 2^16 and beyond the result is INF; between the largest fp16 and 2^16 the two
    // nearest values are 65504 and INF, so a box that reaches past 65504 may overflow.
    if (std::fabs(Wide(v.v)) - Wide(v.err) >= 0x1p16) {
      r.err = 0.0f;
      return r;
    }
    if (top > Wide(kLargestHalf)) {
      r.err = kUnstable;
      return r;
    }
    r.err = RoundUp(Wide(v.err) + HalfStep(top));
    return r;
  }
  r.err = RoundUp(Wide(v.err) + 1.0 / 1024.0);
  return r;
}

Reg AtPrecision(Opcode op, const OpContext& ctx, Precision precision, const Reg& full) {
  OpContext low = ctx;
  for (size_t s = 0; s < low.src.size(); ++s) {
    for (Val& v : low.src[s]) v = ConvertVal(v, precision);
  }
  Reg r = Execute(op, low);
  for (size_t i = 0; i < 4; ++i) {
    Val q = ConvertVal(r[i], precision);
    const Val& f = full[i];
    const bool same = q.v == f.v || (std::isnan(q.v) && std::isnan(f.v));
    double apart = same ? 0.0 : std::fabs(Wide(q.v) - Wide(f.v));
    if (std::isnan(apart)) apart = HUGE_VAL;
    q.err = std::max(q.err, RoundUp(Wide(f.err) + apart));
    if (f.why != kDefined) q.why = f.why;
    q.dev |= f.dev;
    r[i] = q;
  }
  return r;
}

}  // namespace arbiter::arbvp::exec
