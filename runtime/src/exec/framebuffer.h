// The framebuffer object the points are drawn into: RGBA32F colour attachments, one pixel
// per input vector.
#pragma once

#include <string>
#include <vector>

#include "exec/exec_gl.h"

namespace arbiter::runtime::exec {

class Framebuffer {
 public:
  explicit Framebuffer(const ExecGl& gl) : gl_(gl) {}
  ~Framebuffer();
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  // Creates `attachments` RGBA32F renderbuffers of width x height and binds the framebuffer;
  // false (with `error`) when it is incomplete.
  [[nodiscard]] bool Create(int width, int height, int attachments, std::string* error);
  // Draws into the first `count` attachments and clears them to (0,0,0,0).
  void Begin(int count);
  // Reads attachment `index` as RGBA floats, row by row from the bottom.
  void Read(int index, std::vector<float>* pixels);

 private:
  const ExecGl& gl_;
  GLuint framebuffer_ = 0;
  std::vector<GLuint> renderbuffers_;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace arbiter::runtime::exec
