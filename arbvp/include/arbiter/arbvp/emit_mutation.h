// TEST-ONLY: the translator mutations. Each injects ONE plausible translator bug into the
// emitted GLSL, so that a differential verifier (arbiter verify, tests/verify) can prove it
// catches it. Nothing outside tests and the CLI's hidden --mutation flag includes this
// header; an EmitOptions built without it never carries a mutation.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "arbiter/arbvp/emit.h"

namespace arbiter::arbvp {

enum class Mutation : uint8_t {
  None,
  RsqNoAbs,             // RSQ = inversesqrt(x) instead of inversesqrt(abs(x))
  LrpOperandOrder,      // LRP = mix(b, c, a) instead of mix(c, b, a)
  MatrixRowsColumns,    // state.matrix rows read as columns
  LitNoZeroPowZero,     // LIT.z = pow(y, w) without the 0^0 = 1 rule
  LitExponentClamp180,  // LIT clamps w to +-180 instead of +-(128 - eps)
  LitNoYClamp,          // LIT does not clamp y at 0
  SwzSignLost,          // SWZ drops the per-component signs
  SwzZeroOneSwapped,    // SWZ 0 and 1 selectors exchanged
  ArlTruncate,          // ARL truncates towards zero instead of flooring
  SaturateDropped,      // _SAT ignored
  KilOnNaN,             // KIL kills when !(v >= 0), so NaN kills
  KilOnlyX,             // KIL tests only the x component
  FogExpAsExp2,         // ARB_fog_exp uses the exp2 formula
  FogLinearStartEnd,    // ARB_fog_linear with start and end exchanged
  CmpLessEqual,         // CMP selects b when a <= 0 instead of a < 0
  DphNoW,               // DPH ignores b.w
  DstComponents,        // DST y and z exchanged
  XpdOperandOrder,      // XPD = cross(b, a)
  LogNoAbs,             // LOG of x instead of |x|
  ExpFraction,          // EXP.y = t - trunc(t) instead of t - floor(t)
  TxpNoDivide,          // TXP samples like TEX (no divide by q)
  NegationDropped,      // a negated source operand read without its sign
  WriteMaskIgnored,     // every destination written in full
  ScsSinCosSwapped,     // SCS = (sin, cos) instead of (cos, sin)
  PowOperandsSwapped,   // POW = pow(b, a)
  FrcTruncate,          // FRC = x - trunc(x) instead of x - floor(x)
  SgeStrict,            // SGE compares with > instead of >=
  FogColorUnclamped,    // fog options blend the unclamped colour
  // The NV options (NV_vertex_program2/3, NV_fragment_program_option/2).
  CcUpdateIgnored,      // a C suffix does not update the condition code
  CcGtAsGe,             // the GT condition code test reads as GE
  CcWriteMaskIgnored,   // a conditional write mask "(GT.x)" writes every enabled component
  Fp16RoundingDropped,  // H precision (and SHORT storage) computed at fp32
  Fx12ClampDropped,     // X precision rounds to 1/1024 but does not clamp to [-2, 2047/1024]
  SsatUnitRange,        // _SSAT clamps to [0, 1] instead of [-1, 1]
  SsgZeroPositive,      // SSG of 0 gives 1
  DivByVector,          // DIV divides by b's matching components instead of the scalar b.x
  BrkIgnored,           // BRK leaves no loop
  RepCountPlusOne,      // REP runs its block one pass more than its count
  RflNoDouble,          // RFL reflects with (a . d) / (a . a) instead of twice it
  SeqSneSwapped,        // SEQ compares with != and SNE with ==
  kCount,               // not a mutation: the number of enumerators
};

// The stable name of a mutation ("rsq-no-abs"); "none" for Mutation::None.
std::string_view MutationName(Mutation mutation);
// Every mutation except None, in enum order.
std::vector<Mutation> AllMutations();
// Looks a mutation up by name; returns false if unknown.
bool LookupMutation(std::string_view name, Mutation* mutation);

// `options` with `mutation` injected: EmitGlsl and EmitGlslPair (and everything that
// translates with these options, such as a verify of mesa-glsl) then emit the mutated GLSL.
EmitOptions WithMutation(EmitOptions options, Mutation mutation);
// The mutation `options` carries (None unless WithMutation set one).
Mutation MutationOf(const EmitOptions& options);

}  // namespace arbiter::arbvp
