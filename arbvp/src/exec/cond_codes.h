// The condition code registers of the NV program options (CC0, CC1): how an instruction's
// C suffix sets them and how a <ccTest> reads them (NV_vertex_program2_option 2.14.3.X and
// 2.14.4.3, NV_fragment_program_option 3.11.3.X and 3.11.4.3, NV_vertex_program3).
#pragma once

#include <array>
#include <cstdint>

#include "arbiter/arbvp/ir.h"
#include "exec/machine.h"

namespace arbiter::arbvp::exec {

enum class CondCode : uint8_t { GT, EQ, LT, UN };

// One condition code component, with the undefinedness and stability of the value that
// set it: `unstable` when that value's error box reaches another code.
struct CcVal {
  CondCode code = CondCode::EQ;  // "initialized to a vector of EQ values"
  int why = kDefined;
  bool unstable = false;
  uint32_t dev = 0;
};
using CcReg = std::array<CcVal, 4>;

// GenerateCC: UN for NaN, LT below 0, EQ for -0 and +0, GT above.
CcVal GenerateCc(const Val& v);

// What a test decided: `pass`, and whether an undefined (`why`) or unstable condition code
// it read could have decided otherwise.
struct CcOutcome {
  bool pass = true;
  int why = kDefined;
  bool unstable = false;
  uint32_t dev = 0;
  bool certain() const { return why == kDefined && !unstable; }
};

// TestCC of component `i` of a conditional write mask: the swizzled code, tested by the
// rule. An absent test is "(TR)".
CcOutcome TestCcComponent(const CcTest& test, const CcReg& cc, size_t i);

// The condition of BRA, CAL, RET, BRK, IF and KIL <ccTest>: true when any of the four
// swizzled components passes.
CcOutcome TestCcAny(const CcTest& test, const CcReg& cc);

}  // namespace arbiter::arbvp::exec
