// Loading the executor's GL entry points: see exec_gl.h.
#include "exec/exec_gl.h"

#include <fmt/format.h>

#include "exec/context.h"

namespace arbiter::runtime::exec {

bool LoadExecGl(const GetProcFn& get_proc, ExecGl* gl, std::string* error) {
#define ARBITER_EXEC_GL_LOAD(type, member, name)                        \
  if (GlProc proc = get_proc(name); proc != nullptr) {                  \
    gl->member = reinterpret_cast<type>(proc);                          \
  } else {                                                              \
    *error = fmt::format("the GL context does not provide '{}'", name); \
    return false;                                                       \
  }
  ARBITER_EXEC_GL_FUNCTIONS(ARBITER_EXEC_GL_LOAD)
#undef ARBITER_EXEC_GL_LOAD
  return true;
}

bool MakeCurrentAndLoad(GlContext* context, const std::string& name, ExecGl* gl,
                        std::string* error) {
  if (!context->MakeCurrent()) {
    *error = fmt::format("cannot make the {} context current", name);
    return false;
  }
  if (LoadExecGl(context->get_proc(), gl, error)) return true;
  context->Release();
  return false;
}

std::string GlErrorName(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    default:
      return fmt::format("GL error 0x{:04x}", error);
  }
}

}  // namespace arbiter::runtime::exec
