// The shapes of instruction translations shared by emit_instructions.cpp (ARB) and the NV
// files: component-wise, scalar-replicated, whole-vector and per-component results.
#pragma once

#include <fmt/format.h>

#include <string>
#include <utility>
#include <vector>

#include "emit/emit_context.h"

namespace arbiter::arbvp::emit {

inline const SrcOperand& Src(const Instruction& inst, size_t i) { return inst.src[i]; }

inline Expr Call(std::string text, int width) { return {std::move(text), width, true}; }

// A component-wise operation: operands narrowed to the written components, so that
// `ADD t.xz, a, b` becomes `t.xz = a.xz + b.xz;`.
template <typename F>
std::string Componentwise(Context& ctx, const Instruction& inst, F op) {
  return Assign(ctx, inst, [&](const Comps& comps) {
    std::vector<Expr> a;
    for (int i = 0; i < inst.src_count; ++i)
      a.push_back(Source(ctx, Src(inst, static_cast<size_t>(i)), comps));
    return op(a, static_cast<int>(comps.size()));
  });
}

// A scalar operation: the result of one float expression replicated to the written
// components (ARBvp 2.14.5: "the scalar result is replicated").
template <typename F>
std::string ScalarOp(Context& ctx, const Instruction& inst, F op) {
  return Assign(ctx, inst, [&](const Comps& comps) {
    std::vector<Expr> a;
    for (int i = 0; i < inst.src_count; ++i)
      a.push_back(Source(ctx, Src(inst, static_cast<size_t>(i)), {0}));
    return Replicate({op(a), 1, false}, static_cast<int>(comps.size()));
  });
}

// An operation producing a whole vec4, of which the written components are selected.
inline std::string WholeVector(Context& ctx, const Instruction& inst, const Expr& e4) {
  return Assign(ctx, inst, [&](const Comps& comps) { return Select(e4, comps); });
}

// An operation defined component by component (`component(c)` gives component c).
template <typename F>
std::string PerComponent(Context& ctx, const Instruction& inst, F component) {
  return Assign(ctx, inst, [&](const Comps& comps) {
    std::vector<std::string> parts;
    for (int c : comps) parts.push_back(component(c));
    return Construct(parts);
  });
}

// A comparison: 1.0 where `op` holds, else 0.0 (false for NaN but with !=).
inline std::string Compare(Context& ctx, const Instruction& inst, const char* op,
                           const char* function) {
  return Componentwise(ctx, inst, [&](const auto& a, int w) {
    if (w == 1) return Call(fmt::format("float({} {} {})", a[0].text, op, a[1].text), 1);
    return Call(fmt::format("vec{}({}({}, {}))", w, function, a[0].text, a[1].text), w);
  });
}

}  // namespace arbiter::arbvp::emit
