// Binding identity without formatting: the fields a binding's canonical name depends on.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "arbiter/arbvp/ir.h"

namespace arbiter::arbvp {

// Two bindings have equal keys exactly when BindingName spells them the same
// ("vertex.texcoord" and "vertex.texcoord[0]" are one binding). Counting distinct bindings
// by key instead of by name saves formatting a string per bound vector.
struct BindingKey {
  std::array<uint32_t, 5> words{};

  friend bool operator==(const BindingKey&, const BindingKey&) = default;
  friend auto operator<=>(const BindingKey&, const BindingKey&) = default;
};

struct BindingKeyHash {
  size_t operator()(const BindingKey& key) const;
};

// The key of BindingName(binding). With `signed_zero` false, constants that differ only in
// the sign of a zero component share a key (they are numerically equal: the parameter
// count counts them once).
BindingKey KeyOf(const Binding& binding, bool signed_zero = true);

}  // namespace arbiter::arbvp
