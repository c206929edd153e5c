// The readback framebuffer: see framebuffer.h.
#include "exec/framebuffer.h"

#include <fmt/format.h>

namespace arbiter::runtime::exec {

Framebuffer::~Framebuffer() {
  if (framebuffer_ != 0) {
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl_.DeleteFramebuffers(1, &framebuffer_);
  }
  if (!renderbuffers_.empty()) {
    gl_.DeleteRenderbuffers(static_cast<GLsizei>(renderbuffers_.size()), renderbuffers_.data());
  }
}

bool Framebuffer::Create(int width, int height, int attachments, std::string* error) {
  width_ = width;
  height_ = height;
  gl_.GenFramebuffers(1, &framebuffer_);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  renderbuffers_.resize(static_cast<size_t>(attachments));
  gl_.GenRenderbuffers(attachments, renderbuffers_.data());
  for (int i = 0; i < attachments; ++i) {
    gl_.BindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[static_cast<size_t>(i)]);
    gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F_ARB, width, height);
    gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i),
                                GL_RENDERBUFFER, renderbuffers_[static_cast<size_t>(i)]);
  }
  gl_.BindRenderbuffer(GL_RENDERBUFFER, 0);
  const GLenum status = gl_.CheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    *error = fmt::format("the RGBA32F framebuffer ({}x{}, {} attachments) is incomplete (0x{:04x})",
                         width, height, attachments, status);
    return false;
  }
  gl_.Viewport(0, 0, width, height);
  return true;
}

void Framebuffer::Begin(int count) {
  std::vector<GLenum> buffers;
  for (int i = 0; i < count; ++i) buffers.push_back(static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i));
  gl_.DrawBuffers(count, buffers.data());
  gl_.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  gl_.Clear(GL_COLOR_BUFFER_BIT);
}

void Framebuffer::Read(int index, std::vector<float>* pixels) {
  pixels->assign(static_cast<size_t>(width_) * static_cast<size_t>(height_) * 4, 0.0f);
  gl_.ReadBuffer(static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + index));
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, pixels->data());
}

}  // namespace arbiter::runtime::exec
