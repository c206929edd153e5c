// The model's textures as GL texture objects, one per unit.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "arbiter/arbvp/exec.h"
#include "exec/exec_gl.h"

namespace arbiter::runtime::exec {

// Creates and binds every texture of `textures` on its unit (RGBA32F colour, DEPTH32F depth,
// one level, the model's filter, wrap and comparison). The names go to `created` (also on
// failure, for DeleteTextures). False (with `error`) on an inconsistent texture.
// `compatibility` false (core and ES contexts): no GL_DEPTH_TEXTURE_MODE, which they lack.
[[nodiscard]] bool UploadTextures(const ExecGl& gl, const std::map<int, arbvp::Texture>& textures,
                                  std::vector<GLuint>* created, std::string* error,
                                  bool compatibility = true);

// Deletes them (which also unbinds them).
void DeleteTextures(const ExecGl& gl, std::vector<GLuint>* created);

}  // namespace arbiter::runtime::exec
