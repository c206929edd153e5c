// The model's textures as GL texture objects, one per unit.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "arbiter/arbvp/exec.h"
#include "exec/exec_gl.h"

namespace arbiter::runtime::exec {

// Creates and binds every texture of `textures` on its unit (RGBA32F colour, DEPTH32F depth,
// one level, the model's filter, wrap and comparison). The names go to `created` (also on
// failure, for DeleteTextures). False (with `error`) on an inconsistent texture.
// `compatibility` false (core and ES contexts): no GL_DEPTH_TEXTURE_MODE, which they lack.
// A 1D or rectangle texture on a unit of `as_2d` is uploaded as the 2D texture a translation
// emulates it with (N x 1; W x H, arbvp's sampler_emulation.cpp).
[[nodiscard]] bool UploadTextures(const ExecGl& gl, const std::map<int, arbvp::Texture>& textures,
                                  std::vector<GLuint>* created, std::string* error,
                                  bool compatibility = true, const std::set<int>& as_2d = {});

// The GL_DEPTH_TEXTURE_MODE of a model texture's depth mode.
GLint DepthTextureMode(arbvp::DepthMode mode);

// Deletes them (which also unbinds them).
void DeleteTextures(const ExecGl& gl, std::vector<GLuint>* created);

}  // namespace arbiter::runtime::exec
