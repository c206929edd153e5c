// Texture rules: image unit range, one target per unit, SHADOW targets need their option
// (ARBfp 3.11.6, ARB_fragment_program_shadow).
#include <fmt/format.h>

#include <map>

#include "checks.h"

namespace arbiter::arbvp {

void CheckTextures(const CheckContext& ctx) {
  std::map<int, const Instruction*> first_use;
  bool shadow_option = ctx.program.HasOption(OptionId::FragmentProgramShadow);
  for (const Instruction& inst : ctx.program.instructions) {
    if (GetOpcodeInfo(inst.op).signature != OpSignature::Sample) continue;
    constexpr std::string_view kUnits = "arbfp.max_texture_image_units";
    int64_t used = int64_t{inst.tex_unit} + 1;
    if (used > QuietLimit(ctx, kUnits, 0) &&
        !CheckLimit(ctx, kUnits, used, 0, Diag::BindingIndexRange, inst.unit_range,
                    fmt::format("texture image unit {}", inst.tex_unit))) {
      continue;
    }
    if (TexTargetIsShadow(inst.target) && !shadow_option) {
      ctx.Report(Diag::TextureShadowOption, inst.target_range,
                 fmt::format("texture target '{}' needs OPTION ARB_fragment_program_shadow",
                             TexTargetName(inst.target)));
      continue;
    }
    auto [it, fresh] = first_use.emplace(inst.tex_unit, &inst);
    if (!fresh && it->second->target != inst.target) {
      compiler::Diagnostic* d = ctx.Report(
          Diag::TextureTargetConflict, inst.target_range,
          fmt::format("texture unit {} is sampled as '{}' here but as '{}' before; a program "
                      "may use each texture image unit with one target only",
                      inst.tex_unit, TexTargetName(inst.target),
                      TexTargetName(it->second->target)));
      if (d) {
        d->notes.push_back({&ctx.source, it->second->target_range,
                            fmt::format("unit {} first used as '{}' here", inst.tex_unit,
                                        TexTargetName(it->second->target))});
      }
    }
  }
}

}  // namespace arbiter::arbvp
