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
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/arbvp/exec.h"
#include "arbiter/arbvp/ir.h"

namespace arbiter::arbvp::exec {

inline constexpr int kDefined = -1;
// A register component never written (temporaries, address registers): the instruction
// that reads it names the reason.
inline constexpr int kUnwritten = -2;

struct Val {
  float v = 0.0f;
  int why = kDefined;
};
using Reg = std::array<Val, 4>;

inline Reg DefinedReg(const Vec4& v) { return {Val{v[0]}, Val{v[1]}, Val{v[2]}, Val{v[3]}}; }
inline Reg UndefinedReg(const Vec4& v, int why) {
  return {Val{v[0], why}, Val{v[1], why}, Val{v[2], why}, Val{v[3], why}};
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

// A result component computed from `deps`: undefined with the first undefined one's reason.
inline Val From(float v, std::initializer_list<Val> deps) {
  for (const Val& d : deps) {
    if (d.why != kDefined) return {v, d.why};
  }
  return {v, kDefined};
}

// Everything one instruction reads besides its operands.
struct OpContext {
  const Instruction* inst = nullptr;
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

  // A new reason: `what` followed by the instruction's location.
  int Undefined(std::string_view what) const { return reasons->Add(std::string(what) + where); }
};

}  // namespace arbiter::arbvp::exec
