// Condition code generation and tests (cond_codes.h), the TestCC and GenerateCC
// pseudo-code of NV_vertex_program2_option 2.14.4.3 and NV_fragment_program_option 3.11.4.3.
#include "exec/cond_codes.h"

#include <cmath>

namespace arbiter::arbvp::exec {
namespace {

// TestCC(field) for one rule. "Comparisons involving condition codes of UN evaluate to true
// for NE and false otherwise" (TR aside).
bool TestCc(CcRule rule, CondCode code) {
  switch (rule) {
    case CcRule::EQ:
      return code == CondCode::EQ;
    case CcRule::NE:
      return code != CondCode::EQ;
    case CcRule::LT:
      return code == CondCode::LT;
    case CcRule::GE:
      return code == CondCode::GT || code == CondCode::EQ;
    case CcRule::LE:
      return code == CondCode::LT || code == CondCode::EQ;
    case CcRule::GT:
      return code == CondCode::GT;
    case CcRule::TR:
      return true;
    case CcRule::FL:
      return false;
  }
  return true;
}

}  // namespace

CcVal GenerateCc(const Val& v) {
  CcVal cc;
  if (std::isnan(v.v)) {
    cc.code = CondCode::UN;
  } else if (v.v < 0.0f) {
    cc.code = CondCode::LT;
  } else if (v.v == 0.0f) {
    cc.code = CondCode::EQ;
  } else {
    cc.code = CondCode::GT;
  }
  cc.why = v.why;
  cc.dev = v.dev;
  // The box of an inexact value reaches 0 (another code), or is unbounded.
  cc.unstable = std::isinf(v.err) || (v.err > 0.0f && !(std::fabs(v.v) > v.err));
  return cc;
}

CcOutcome TestCcComponent(const CcTest& test, const CcReg& cc, size_t i) {
  if (!test.present || test.rule == CcRule::TR) return {};
  if (test.rule == CcRule::FL) return {false};
  const Swz sel = test.swizzle[i];
  const CcVal& field = cc[sel <= Swz::W ? static_cast<size_t>(sel) : i];
  return {TestCc(test.rule, field.code), field.why, field.unstable, field.dev};
}

CcOutcome TestCcAny(const CcTest& test, const CcReg& cc) {
  CcOutcome any{false};
  for (size_t i = 0; i < 4; ++i) {
    CcOutcome one = TestCcComponent(test, cc, i);
    // A certain pass decides alone; otherwise every uncertain field may change the outcome.
    if (one.pass && one.certain()) return one;
    any.pass = any.pass || one.pass;
    if (any.why == kDefined) any.why = one.why;
    any.unstable = any.unstable || one.unstable;
    any.dev |= one.dev;
  }
  return any;
}

}  // namespace arbiter::arbvp::exec
