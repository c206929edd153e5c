// The test-only translator mutations (emit_mutation.h): their names, and the options that
// carry one.
#include <array>

#include "arbiter/arbvp/emit_mutation.h"

namespace arbiter::arbvp {
namespace {

constexpr std::array<std::string_view, static_cast<size_t>(Mutation::kCount)> kNames = {
    "none",
    "rsq-no-abs",
    "lrp-operand-order",
    "matrix-rows-columns",
    "lit-no-zero-pow-zero",
    "lit-exponent-clamp-180",
    "lit-no-y-clamp",
    "swz-sign-lost",
    "swz-zero-one-swapped",
    "arl-truncate",
    "saturate-dropped",
    "kil-on-nan",
    "kil-only-x",
    "fog-exp-as-exp2",
    "fog-linear-start-end",
    "cmp-less-equal",
    "dph-no-w",
    "dst-components",
    "xpd-operand-order",
    "log-no-abs",
    "exp-fraction",
    "txp-no-divide",
    "negation-dropped",
    "write-mask-ignored",
    "scs-sin-cos-swapped",
    "pow-operands-swapped",
    "frc-truncate",
    "sge-strict",
    "fog-color-unclamped",
    "cc-update-ignored",
    "cc-gt-as-ge",
    "cc-write-mask-ignored",
    "fp16-rounding-dropped",
    "fx12-clamp-dropped",
    "ssat-unit-range",
    "ssg-zero-positive",
    "div-by-vector",
    "brk-ignored",
    "rep-count-plus-one",
    "rfl-no-double",
    "seq-sne-swapped",
};

}  // namespace

std::string_view MutationName(Mutation mutation) {
  size_t i = static_cast<size_t>(mutation);
  return i < kNames.size() ? kNames[i] : "none";
}

std::vector<Mutation> AllMutations() {
  std::vector<Mutation> out;
  for (size_t i = 1; i < kNames.size(); ++i) out.push_back(static_cast<Mutation>(i));
  return out;
}

bool LookupMutation(std::string_view name, Mutation* mutation) {
  for (size_t i = 0; i < kNames.size(); ++i) {
    if (kNames[i] == name) {
      *mutation = static_cast<Mutation>(i);
      return true;
    }
  }
  return false;
}

EmitOptions WithMutation(EmitOptions options, Mutation mutation) {
  options.mutation_ = mutation;
  return options;
}

Mutation MutationOf(const EmitOptions& options) { return options.mutation_; }

}  // namespace arbiter::arbvp
