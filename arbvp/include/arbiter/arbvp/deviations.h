// The places where Mesa computes a value the ARB specs define differently (measured on Mesa
// 22.3; tests/exec/mesa-deviations.txt pins each one). The interpreter marks every output
// component that depends on one (OutputRegister::deviations) so that `arbiter verify` leaves
// it out of the comparison with an engine and driver the deviation applies to.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace arbiter::arbvp {

enum Deviation : uint32_t {
  kDevNanClamp = 1u << 0,              // MIN, MAX, _SAT, LIT's clamps of NaN: Mesa's other operand
  kDevLrpInfinite = 1u << 1,           // LRP of an infinity: Mesa's c + a * (b - c) gives NaN
  kDevLitZeroPowZero = 1u << 2,        // LIT 0^0: the spec's 1, llvmpipe's 0
  kDevFogWithDrawBuffers = 1u << 3,    // a fog option with ARB_draw_buffers: Mesa does not fog
  kDevNonFiniteLlvmpipe = 1u << 4,     // computed from a NaN or an infinity: llvmpipe loses them
  kDevCubeEdgeLlvmpipe = 1u << 5,      // a linear cube lookup across a face edge: llvmpipe's
                                       // seamless filtering
  kDevMirrorCentreSoftpipe = 1u << 6,  // a linear mirrored lookup at a texel centre: softpipe
  kDevNanCompareFolded = 1u << 7,      // SGE/SLT of a NaN: the GLSL compiler's folded compare
  kDevNanFromInfinities = 1u << 8,     // inf - inf: Mesa's finite-number identities avoid it
  kDevPointFacingSoftpipe = 1u << 9,   // fragment.facing of a point: softpipe's core and ES
                                       // contexts say back-facing
};

struct DeviationInfo {
  Deviation bit;
  std::string_view name;    // "min-max-nan"
  bool mesa_arb = false;    // Mesa running the ARB program deviates
  bool mesa_glsl = false;   // Mesa running the GLSL translation deviates
  std::string_view driver;  // "" for every driver, else the one that deviates
  std::string_view what;    // one sentence
};

const std::vector<DeviationInfo>& KnownDeviations();

// The deviations that apply to `engine` ("mesa-arb" or "mesa-glsl") on `driver`.
uint32_t ApplicableDeviations(std::string_view engine, std::string_view driver);

}  // namespace arbiter::arbvp
