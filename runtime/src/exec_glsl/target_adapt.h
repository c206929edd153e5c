// Adapting a target translation (glsl330, es300, es100, vk450: state as uniforms, named varyings
// and outputs) for readback, the way glsl_adapt.h adapts the GLSL 1.10 one: its `main`
// becomes `arbiter_main`, and a generated `main` calls it and copies the results to colour
// attachments. What a result is called is read from the translation's binding map
// (BindingMap::outputs, ::inputs), not from the emitter's naming conventions.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "arbiter/arbvp/emit.h"
#include "arbiter/arbvp/exec.h"
#include "arbiter/runtime/exec.h"
#include "arbiter/runtime/translate.h"
#include "exec/program_rewrite.h"
#include "exec_glsl/glsl_adapt.h"

namespace arbiter::runtime::exec {

// The shading-language dialect of a target engine's generated shaders.
struct TargetDialect {
  arbvp::EmitTarget target = arbvp::EmitTarget::Glsl330;
  // GLSL ES 1.00: attribute/varying and gl_FragData (with GL_EXT_draw_buffers) instead of
  // in/out and layout-qualified fragment outputs.
  bool legacy_io = false;
  // GLSL 4.50 for Vulkan: every stage input and output declares its location, as the
  // translation's own do (`layout(location = N) in vec4 NAME;`).
  bool locations = false;
  std::string header;  // "#version 330 core\n", with the default precisions in ES
};
TargetDialect DialectOf(arbvp::EmitTarget target);

// The attributes of one point, vector `v` at clip position `clip`, each given to
// put(location, value): for a fragment program alone the generated inputs
// (kFragmentInputAttribs, the clip position among them); else every attribute of `map` at
// its location (0..15), and the clip position at plan.position_attrib when it has one. False
// (with `error`) for an attribute that no input of the model feeds.
[[nodiscard]] bool PointAttributes(const RunPlan& plan, const arbvp::BindingMap& map,
                                   const arbvp::InputVector& v, const arbvp::Vec4& clip,
                                   const std::function<void(int, const arbvp::Vec4&)>& put,
                                   std::string* error);

// The translation of `programs` to `target` with state as uniforms (emit's mutation kept),
// as a target engine runs it. False with the refusal (construct and target) in
// `not_applicable`, or with `error`.
[[nodiscard]] bool TranslateForTarget(const ArbPrograms& programs, const arbvp::EmitOptions& emit,
                                      arbvp::EmitTarget target,
                                      const compiler::SourceFile* vertex_source,
                                      const compiler::SourceFile* fragment_source,
                                      CheckedTranslation* translation, std::string* not_applicable,
                                      std::string* error);

// Plans the passes for `plan` (from PlanRun on the same programs) and `translation` (of
// dialect.target). False (with `error`) when the translation or its binding map does not
// have the expected shape.
[[nodiscard]] bool PlanTargetPasses(const RunPlan& plan, const CheckedTranslation& translation,
                                    const TargetDialect& dialect, int max_attachments,
                                    std::vector<GlslPass>* passes, std::string* error);

}  // namespace arbiter::runtime::exec
