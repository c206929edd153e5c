// Comparing results with expectations (case_compare.h).
#include "case_compare.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>

namespace arbiter::exec_cases {
namespace {

uint32_t Bits(float f) {
  uint32_t u = 0;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

}  // namespace

// The comparison of cases.h: Exact is bit equality (any NaN matches any NaN).
bool Matches(float got, float want, Tolerance tolerance, float bound) {
  if (std::isnan(want)) return std::isnan(got);
  if (std::isnan(got)) return false;
  switch (tolerance) {
    case Tolerance::Exact:
      return Bits(got) == Bits(want);
    case Tolerance::Relative:
      if (std::isinf(want) || std::isinf(got)) return got == want;
      return std::fabs(got - want) <= bound * std::fabs(want);
    case Tolerance::Absolute:
      if (std::isinf(want) || std::isinf(got)) return got == want;
      return std::fabs(got - want) <= bound;
  }
  return false;
}

std::string Describe(const arbvp::VectorResult& r) {
  std::ostringstream out;
  if (r.killed) out << "killed ";
  for (const arbvp::OutputRegister& o : r.outputs) {
    out << o.name << " = (";
    for (size_t i = 0; i < 4; ++i) {
      out << (i ? ", " : "") << ((o.written >> i) & 1 ? std::to_string(o.value[i]) : "-");
      if (!o.undefined[i].empty()) out << " [" << o.undefined[i] << "]";
    }
    out << ")\n";
  }
  return out.str();
}

}  // namespace arbiter::exec_cases
