// The mesa-glsl engine: runs the GLSL translation of ARB programs on the executor's context
// (ArbExecutor::RunTranslated).
#pragma once

#include <string>
#include <vector>

#include "arbiter/arbvp/emit.h"
#include "arbiter/arbvp/exec.h"
#include "arbiter/runtime/exec.h"
#include "exec/exec_gl.h"
#include "exec/program_cache.h"
#include "exec/program_rewrite.h"
#include "exec_glsl/glsl_adapt.h"

namespace arbiter::runtime::exec {

// What the engine keeps between runs on one context: glslang's verdict on the last
// translation (the same text gets the same verdict) and the linked programs of the last
// few passes.
struct GlslCache {
  std::string vertex;  // the last translation self-checked
  std::string fragment;
  bool checked = false;
  bool ok = false;
  std::string error;
  ProgramCache programs{8};
};

// Shared with the target engines (target_run.h): a GL error after `step` as `error`; the
// components GLSL carries of a result (x of the fog coordinate and point size, z of the
// depth); and the linked program of `pass`, from `cache` or linked now (LinkGlslPass).
[[nodiscard]] bool CheckGl(const ExecGl& gl, const char* step, std::string* error);
uint8_t GlslComponents(const arbvp::Binding& b);
GLuint LinkCached(const ExecGl& gl, const GlslPass& pass, const arbvp::BindingMap& map,
                  const RunPlan& plan, ProgramCache* cache, std::string* error);

// Translates `programs` (with the glslang self-check), adapts the shaders for readback
// (glsl_adapt.h) and runs them on `inputs` in the current context. Results as
// ArbExecutor::Run gives them, except that the written mask of result.fogcoord and
// result.pointsize keeps only x, and that of result.depth only z: GLSL carries no other
// component of them.
[[nodiscard]] bool RunGlslTranslation(const ExecGl& gl, const ContextLimits& limits,
                                      const ArbPrograms& programs, const arbvp::EmitOptions& emit,
                                      const arbvp::ExecInputs& inputs, GlslCache* cache,
                                      std::vector<arbvp::VectorResult>* results,
                                      std::string* error);

}  // namespace arbiter::runtime::exec
