// The inputs' initial values, the state.* bindings (the ARB specs' derivations, ARBvp
// 2.14.3.2 tables X.3.2-X.3.8 and ARBfp 3.11.3.2, live in arbiter/glstate/values.h), and
// the stable order of results.
#include "arbiter/arbvp/exec.h"
#include "arbiter/glstate/values.h"
#include "exec/state_internal.h"

namespace arbiter::arbvp {

VertexInput::VertexInput() {
  texcoord.fill(Vec4{0.0f, 0.0f, 0.0f, 1.0f});
  generic.fill(Vec4{0.0f, 0.0f, 0.0f, 1.0f});
}

FragmentInput::FragmentInput() { texcoord.fill(Vec4{0.0f, 0.0f, 0.0f, 1.0f}); }

// The derivations are glstate's (values.h), compiled here under this library's
// -ffp-contract=off: the host library computes the same values.
Vec4 ReadStateBinding(const GlState& state, const Binding& b) {
  return glstate::StateValue(state, StateRefOf(b));
}

std::string StateBindingUndefined(const GlState& state, const Binding& b) {
  if (b.kind != BindingKind::State) return {};
  return std::string(glstate::StateUndefined(state, StateRefOf(b)));
}

namespace {

// Rank of a result register in the stable order; ties are broken by index.
int ResultRank(const Binding& b) {
  switch (b.result) {
    case ResultReg::Position:
      return 0;
    case ResultReg::Color:
      return 1 + (b.face == Face::Back ? 2 : 0) + (b.secondary ? 1 : 0);
    case ResultReg::FogCoord:
      return 5;
    case ResultReg::PointSize:
      return 6;
    case ResultReg::TexCoord:
      return 7;
    case ResultReg::ClipDistance:
      return 8;
    case ResultReg::FragColor:
      return 9;
    case ResultReg::FragDepth:
      return 10;
  }
  return 11;
}

}  // namespace

bool ResultRegOrder(const Binding& a, const Binding& b) {
  int ra = ResultRank(a);
  int rb = ResultRank(b);
  if (ra != rb) return ra < rb;
  return a.index < b.index;
}

}  // namespace arbiter::arbvp
