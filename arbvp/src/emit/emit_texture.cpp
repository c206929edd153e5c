// Texture sampling (emit_texture.h). Fragment shaders sample with the GLSL 1.10 functions;
// a vertex shader has no implicit level of detail, so vertex programs (NV_vertex_program3
// 2.14.5.45-48: "the base LOD value for vertex texture lookups is defined to be zero") use
// the Lod functions. Explicit levels and derivatives in a fragment shader, and derivatives
// anywhere, come from GL_ARB_shader_texture_lod.
#include <fmt/format.h>

#include "emit/emit_context.h"
#include "emit/emit_shapes.h"

namespace arbiter::arbvp::emit {
namespace {

// What the translation needs of a target (texture_targets.def): the GLSL function's base
// name, the coordinate components it reads (x.. up to the last one the target reads: a
// shadow target's depth reference is in r, as ARB_fragment_program_shadow puts it), the
// components of its derivatives, whether it has Lod and bias forms (rectangle textures have
// no mipmaps and GLSL no Lod function for them), and whether it has a Proj form.
struct TargetRow {
  const char* function;
  int coords;  // components x.. of the coordinate
  int grad;    // components x.. of a derivative
  bool lod;
  bool proj;
};

// The components x.. up to the highest one in `mask`.
constexpr int Width(unsigned mask) { return mask == 0 ? 0 : 1 + Width(mask >> 1); }

constexpr TargetRow kTargets[] = {
#define ARBVP_TEX_TARGET(name, spelling, coords, shadow, dim, grad, mipmaps, depth, sampler, \
                         lookup, proj, spec)                                                 \
  {lookup, Width(coords), grad, mipmaps, proj},
#include "arbiter/arbvp/texture_targets.def"
#undef ARBVP_TEX_TARGET
};

const TargetRow& Row(TexTarget target) { return kTargets[static_cast<size_t>(target)]; }

Comps First(int n) {
  Comps out;
  for (int c = 0; c < n; ++c) out.push_back(c);
  return out;
}

enum class SampleKind { Plain, Projective, Bias, Lod };

// The sampler of the instruction's unit, declared with its target.
std::string Sampler(Context& ctx, const Instruction& inst) {
  ctx.samplers[inst.tex_unit] = inst.target;
  if (!Row(inst.target).lod) ctx.needs_rect = true;
  return SamplerName(inst.tex_unit);
}

// A rectangle texture at an explicit level: its only effect is the choice between the
// minification and magnification filters, which derivatives of length 2^lod reproduce
// (rho = 2^lod, ARB_shader_texture_lod equation 3.21c).
std::string RectAtLevel(Context& ctx, const Instruction& inst, const std::string& sampler,
                        const std::string& coord, const std::string& lod) {
  ctx.needs_texture_lod = true;
  return fmt::format("{}GradARB({}, {}, vec2(exp2({}), 0.0), vec2(0.0, exp2({})))",
                     Row(inst.target).function, sampler, coord, lod, lod);
}

std::string Sample(Context& ctx, const Instruction& inst, SampleKind kind) {
  if (kind == SampleKind::Projective && ctx.Mutated(Mutation::TxpNoDivide))
    kind = SampleKind::Plain;
  const TargetRow& row = Row(inst.target);
  const std::string sampler = Sampler(ctx, inst);
  const std::string f = row.function;
  const SrcOperand& coord = Src(inst, 0);
  const bool vertex = ctx.IsVertex();
  // The level of detail a vertex lookup or TXL gives explicitly: TXB in a vertex program
  // "is completely equivalent to the TXL instruction" (NV_vertex_program3 2.14.5.46).
  std::string lod;
  if (kind == SampleKind::Lod || (vertex && kind == SampleKind::Bias)) {
    lod = Source(ctx, coord, {3}).text;
  } else if (vertex) {
    lod = "0.0";
  }
  if (!vertex && kind == SampleKind::Lod && row.lod) ctx.needs_texture_lod = true;
  const std::string suffix = lod.empty() || !row.lod ? "" : "Lod";
  const std::string lod_arg = lod.empty() || !row.lod ? "" : ", " + lod;
  std::string text;
  if (kind == SampleKind::Projective && !row.proj) {
    // GLSL has no textureCubeProj: divide s, t, r by q ourselves.
    text = fmt::format("{}{}({}, {} / {}{})", f, suffix, sampler,
                       Source(ctx, coord, First(row.coords)).text, Source(ctx, coord, {3}).text,
                       lod_arg);
  } else if (kind == SampleKind::Projective) {
    // The ...Proj functions with a vec4 divide the coordinates (and r) by q.
    text = fmt::format("{}Proj{}({}, {}{})", f, suffix, sampler,
                       Source(ctx, coord, AllComps()).text, lod_arg);
  } else if (!row.lod && !lod.empty() && lod != "0.0") {
    text = RectAtLevel(ctx, inst, sampler, Source(ctx, coord, First(row.coords)).text, lod);
  } else {
    text = fmt::format("{}{}({}, {}{}", f, suffix, sampler,
                       Source(ctx, coord, First(row.coords)).text, lod_arg);
    // TXB: w is the LOD bias. Rectangle textures have no mipmaps and GLSL no bias form.
    if (kind == SampleKind::Bias && row.lod && !vertex) text += ", " + Source(ctx, coord, {3}).text;
    text += ")";
  }
  return WholeVector(ctx, inst, Call(text, 4));
}

}  // namespace

std::string TEX(Context& ctx, const Instruction& inst) {
  return Sample(ctx, inst, SampleKind::Plain);
}
std::string TXB(Context& ctx, const Instruction& inst) {
  return Sample(ctx, inst, SampleKind::Bias);
}
std::string TXP(Context& ctx, const Instruction& inst) {
  return Sample(ctx, inst, SampleKind::Projective);
}

// TXL: w is the level of detail ("rho(x,y) is given by 2^w", NV_fragment_program2 3.11.6.6).
std::string TXL(Context& ctx, const Instruction& inst) {
  return Sample(ctx, inst, SampleKind::Lod);
}

// TXD: the level of detail from the derivatives d/dx = b, d/dy = c (NV_fragment_program_option
// 3.11.6.5), which the GradARB functions take as they are.
std::string TXD(Context& ctx, const Instruction& inst) {
  const TargetRow& row = Row(inst.target);
  const std::string sampler = Sampler(ctx, inst);
  ctx.needs_texture_lod = true;
  std::string text = fmt::format("{}GradARB({}, {}, {}, {})", row.function, sampler,
                                 Source(ctx, Src(inst, 0), First(row.coords)).text,
                                 Source(ctx, Src(inst, 1), First(row.grad)).text,
                                 Source(ctx, Src(inst, 2), First(row.grad)).text);
  return WholeVector(ctx, inst, Call(text, 4));
}

}  // namespace arbiter::arbvp::emit
