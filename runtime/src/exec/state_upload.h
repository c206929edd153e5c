// Feeding the model's GL state and program parameters to the context.
#pragma once

#include "arbiter/arbvp/exec.h"
#include "exec/exec_gl.h"

namespace arbiter::runtime::exec {

// Sets every item of `state` that a state.* binding reads. Light positions, spot directions,
// clip planes and texgen eye planes are given with the identity modelview, so GL stores
// exactly the model's eye-space values; the modelview is loaded after them.
void UploadGlState(const ExecGl& gl, const arbvp::GlState& state);

// Sets program.env[0..kMaxProgramParams) of `target` (indices missing from `env` to 0, since
// env parameters outlive a run).
void UploadEnvParameters(const ExecGl& gl, GLenum target, const std::map<int, arbvp::Vec4>& env);

// Sets every local parameter of the bound program: those of `local`, zero elsewhere.
void UploadLocalParameters(const ExecGl& gl, GLenum target,
                           const std::map<int, arbvp::Vec4>& local);

}  // namespace arbiter::runtime::exec
