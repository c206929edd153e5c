// A small cache of compiled GL programs, keyed by their full source text: running the same
// program on several input batches (verify's edge and random batches, exec's repeated
// runs) compiles it once. Only the text decides, so a cached program is exactly what a
// fresh compile would give; every per-run value (parameters, uniforms) is set again by the
// caller on each run.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "exec/exec_gl.h"

namespace arbiter::runtime::exec {

class ProgramCache {
 public:
  explicit ProgramCache(size_t capacity) : capacity_(capacity) {}

  // The program compiled from `key`, or 0; a hit becomes the most recently used.
  GLuint Find(const std::string& key);
  // Keeps `id` under `key`. Returns the least recently used program it pushed out (0 if
  // none): the caller deletes it with its kind's call, in the current context.
  [[nodiscard]] GLuint Add(std::string key, GLuint id);

 private:
  size_t capacity_;
  std::vector<std::pair<std::string, GLuint>> entries_;  // most recently used first
};

}  // namespace arbiter::runtime::exec
