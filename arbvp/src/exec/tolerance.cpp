// The bounds of the tolerance model (tolerance.h).
#include "exec/tolerance.h"

#include <algorithm>

namespace arbiter::arbvp::exec {

float RoundUp(double e) {
  if (!(e < static_cast<double>(std::numeric_limits<float>::max()))) return kUnstable;
  float f = static_cast<float>(e);
  if (static_cast<double>(f) < e) f = std::nextafter(f, kUnstable);
  return f;
}

float Spread::Bound(double magnitude, double rel, double abs, bool reformulated) const {
  if (bad_) return kUnstable;
  // An infinity that finite terms overflowed to: a compiler that reassociates ((a*b)*c as
  // a*(b*c)) may stay finite, as within a factor of 8 of overflow below.
  if (!std::isfinite(v_)) return overflow_ && reformulated ? kUnstable : 0.0f;
  double v = std::fabs(static_cast<double>(v_));
  double e = spread_;
  if (spread_ > 0.0 || reformulated) {
    e += kRounding * std::max(magnitude, v);
    // Within a factor of 8 of overflow, a compiler that reassociates (a*b + a*c as
    // a*(b + c)) may overflow where the reference does not.
    if (std::max({magnitude, v, largest_}) + e > 0x1p125) return kUnstable;
  }
  e += rel * v + abs;
  const double kMin = Wide(std::numeric_limits<float>::min());
  if (v < kMin && (v != 0.0 || spread_ > 0.0)) e += kMin;
  if (v + e > static_cast<double>(std::numeric_limits<float>::max())) return kUnstable;
  return RoundUp(e);
}

}  // namespace arbiter::arbvp::exec
