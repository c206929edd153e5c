// The known Mesa deviations (deviations.h). Signed zeros (Mesa turns -0 into +0 through
// varyings and clamps) and flushed denormals are not here: the tolerance model absorbs them.
#include "arbiter/arbvp/deviations.h"

namespace arbiter::arbvp {

const std::vector<DeviationInfo>& KnownDeviations() {
  static const std::vector<DeviationInfo> kTable = {
      {kDevNanClamp, "nan-clamp", true, true, "",
       "MIN, MAX, _SAT and LIT's clamps are IEEE minNum/maxNum in Mesa: a NaN operand gives the "
       "other operand (0 for a clamp) where the specs' comparisons keep NaN"},
      {kDevLrpInfinite, "lrp-infinite", true, true, "",
       "LRP (and mix) is c + a * (b - c) in Mesa: an infinite operand gives NaN where the "
       "specs' a * b + (1 - a) * c gives an infinity"},
      {kDevLitZeroPowZero, "lit-zero-pow-zero", true, false, "llvmpipe",
       "LIT with y = 0 and w = 0: the spec's 0^0 is 1, llvmpipe computes 0"},
      {kDevFogWithDrawBuffers, "fog-with-draw-buffers", true, false, "",
       "a program with a fog option and ARB_draw_buffers is not fogged at all by Mesa"},
      {kDevNonFiniteLlvmpipe, "llvmpipe-nonfinite", true, true, "llvmpipe",
       "llvmpipe does not keep NaN and infinity: its MIN/MAX, EX2, LG2, POW, RSQ and "
       "multiply-add code turn them into numbers or NaN, so nothing computed from a NaN or an "
       "infinity is compared on llvmpipe (softpipe is)"},
      {kDevCubeEdgeLlvmpipe, "llvmpipe-cube-edge", true, true, "llvmpipe",
       "a linearly filtered cube map lookup whose footprint crosses a face edge: llvmpipe "
       "filters across faces (seamless), the GL 2.0 lookup wraps within the face"},
      {kDevMirrorCentreSoftpipe, "softpipe-mirror-centre", true, true, "softpipe",
       "a LINEAR lookup with MIRRORED_REPEAT exactly at a texel centre of a mirrored period "
       "(s = -0.375 on 4 texels): softpipe returns the neighbouring texel"},
      {kDevNanCompareFolded, "nan-compare-folded", false, true, "",
       "SGE or SLT with a NaN operand, which the specs' comparison makes 0: Mesa's GLSL "
       "compiler folds a product of two comparisons sharing an operand, (a >= b) * (a >= c), "
       "into one comparison with max or min, a >= max(b, c), whose maxNum drops the NaN, so "
       "the product takes the other comparison's result"},
      {kDevNanFromInfinities, "nan-from-infinities", true, true, "",
       "a NaN that IEEE arithmetic makes of infinities (inf - inf): Mesa's compilers use "
       "identities that hold for finite numbers only (x - x = 0 in XPD of a vector with "
       "itself, a * b + a = a * (b + 1)) and give 0 or an infinity"},
      {kDevPointFacingSoftpipe, "softpipe-point-facing", false, false, "softpipe",
       "fragment.facing of a point on a core or ES context (the target engines): points are "
       "front-facing (OpenGL 3.3 section 3.6.1), softpipe's gl_FrontFacing says back-facing "
       "(llvmpipe and the compatibility contexts say front-facing)"},
  };
  return kTable;
}

uint32_t ApplicableDeviations(std::string_view engine, std::string_view driver) {
  uint32_t mask = 0;
  for (const DeviationInfo& d : KnownDeviations()) {
    bool engine_applies =
        (engine == "mesa-arb" && d.mesa_arb) || (engine == "mesa-glsl" && d.mesa_glsl);
    if (engine_applies && (d.driver.empty() || d.driver == driver)) mask |= d.bit;
  }
  return mask;
}

}  // namespace arbiter::arbvp
