// The interpreter's register model: float32 components that carry why the specs leave them
// undefined, and the context one instruction executes in.
//
// Undefinedness is tracked per component. A component is defined (why == kDefined) or
// holds the index of a reason in the run's Reasons. An operation's result component takes
// the reason of the first undefined source component it depends on (so a tag always names
// the instruction where the undefined value arose, not where it was last copied), unless
// the operation itself makes it undefined (LG2 of 0, XPD.w, ...), which adds a new reason.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/arbvp/deviations.h"
#include "arbiter/arbvp/exec.h"
#include "arbiter/arbvp/ir.h"

namespace arbiter::arbvp::exec {

// A float widened for the tolerance model's double arithmetic.
inline double Wide(float x) { return static_cast<double>(x); }

inline constexpr int kDefined = -1;
// A register component never written (temporaries, address registers): the instruction
// that reads it names the reason.
inline constexpr int kUnwritten = -2;

// `err` bounds |v - (what a conforming implementation computes)| under the tolerance model
// (tolerance.h); +inf when the value is within rounding of a discontinuity. `dev` holds the
// known Mesa deviations (deviations.h) the value depends on.
struct Val {
  float v = 0.0f;
  int why = kDefined;
  float err = 0.0f;
  uint32_t dev = 0;
};
using Reg = std::array<Val, 4>;

// An input value: exact, except that a denormal may reach the program flushed to zero.
inline Val InputVal(float v, int why = kDefined) {
  bool denormal = v != 0.0f && std::fabs(v) < std::numeric_limits<float>::min();
  return {v, why, denormal ? std::numeric_limits<float>::min() : 0.0f,
          std::isfinite(v) ? 0u : kDevNonFiniteLlvmpipe};
}
inline Reg DefinedReg(const Vec4& v) {
  return {InputVal(v[0]), InputVal(v[1]), InputVal(v[2]), InputVal(v[3])};
}
inline Reg UndefinedReg(const Vec4& v, int why) {
  return {InputVal(v[0], why), InputVal(v[1], why), InputVal(v[2], why), InputVal(v[3], why)};
}

// The reasons of one run (one input vector, or a vertex + fragment pair).
class Reasons {
 public:
  int Add(std::string text) {
    auto it = index_.find(text);
    if (it != index_.end()) return it->second;
    int id = static_cast<int>(list_.size());
    index_.emplace(text, id);
    list_.push_back(std::move(text));
    return id;
  }
  const std::string& Get(int id) const { return list_[static_cast<size_t>(id)]; }

 private:
  std::vector<std::string> list_;
  std::map<std::string, int> index_;
};

// A result component computed from `deps`: undefined with the first undefined one's reason,
// depending on all their deviations, and on kDevNanFromInfinities when it is a NaN made of
// infinities (inf - inf). The error bound is the caller's (tolerance.h).
inline Val From(float v, std::initializer_list<Val> deps, float err = 0.0f) {
  Val r{v, kDefined, err, std::isfinite(v) ? 0u : kDevNonFiniteLlvmpipe};
  bool nan_operand = false;
  bool infinite_operand = false;
  for (const Val& d : deps) {
    if (r.why == kDefined) r.why = d.why;
    r.dev |= d.dev;
    nan_operand = nan_operand || std::isnan(d.v);
    infinite_operand = infinite_operand || std::isinf(d.v);
  }
  if (std::isnan(v) && infinite_operand && !nan_operand) r.dev |= kDevNanFromInfinities;
  return r;
}

// What every result of a run depends on beyond its own value: a control flow decision on an
// undefined or unstable condition, or an abnormal termination (NV options).
struct Taint {
  int why = kDefined;
  bool unstable = false;
  uint32_t dev = 0;
  void Add(int w, bool u, uint32_t d) {
    if (why == kDefined) why = w;
    unstable = unstable || u;
    dev |= d;
  }
};

// Everything one instruction reads besides its operands.
struct OpContext {
  const Instruction* inst = nullptr;
  ProgramKind kind = ProgramKind::Vertex;
  std::array<Reg, 3> src{};  // loaded operands: swizzled (extended for SWZ) and negated
  Reasons* reasons = nullptr;
  std::string where;  // " at line:col" of the instruction, or "" without a source
  // Sampling instructions.
  const std::map<int, Texture>* textures = nullptr;
  bool shadow_option = false;
  // KIL: `killed` when the fragment is discarded, `killed_defined` when a defined value
  // decided it; otherwise kill_why names the undefined value the outcome depends on.
  bool killed = false;
  bool killed_defined = false;
  int kill_why = kDefined;
  // Whether the KIL outcome is within rounding of its threshold, and the deviations it
  // depends on.
  bool kill_unstable = false;
  uint32_t kill_dev = 0;

  // A new reason: `what` followed by the instruction's location.
  int Undefined(std::string_view what) const { return reasons->Add(std::string(what) + where); }
};

}  // namespace arbiter::arbvp::exec
