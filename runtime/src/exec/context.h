// The GL context the executor draws with: OSMesa (context_osmesa.cpp) or EGL surfaceless
// (context_egl.cpp). Both draw into the executor's own framebuffer object.
#pragma once

#include <memory>
#include <string>

#include "exec/exec_gl.h"

namespace arbiter::runtime::exec {

class GlContext {
 public:
  virtual ~GlContext() = default;
  // Binds the context to the calling thread; false when the platform refuses.
  [[nodiscard]] virtual bool MakeCurrent() = 0;
  // Unbinds it again.
  virtual void Release() = 0;
  // The context's entry point lookup.
  virtual GetProcFn get_proc() const = 0;
};

// Makes `context` current and loads its entry points into `gl`; on failure (with `error`:
// "cannot make the NAME context current", or the missing entry point) nothing is current.
[[nodiscard]] bool MakeCurrentAndLoad(GlContext* context, const std::string& name, ExecGl* gl,
                                      std::string* error);

// Sets Mesa's environment (GALLIUM_DRIVER = `driver`, which the caller has validated; no
// shader cache) before any context exists.
void SetMesaEnvironment(const std::string& driver);

// Loads libOSMesa (with LLVM) into this process without creating a context, before worker
// processes are forked: each worker then starts with the library loaded and relocated
// instead of paying tens of milliseconds for it. Nothing of Mesa runs yet (no driver, no
// threads a fork would lose). EGL has no counterpart: its driver loads when the display is
// initialised, which starts driver threads.
void PreloadOsMesa();

// A compatibility-profile context; null (with `error` set) on failure.
std::unique_ptr<GlContext> CreateOsMesaContext(std::string* error);
std::unique_ptr<GlContext> CreateEglContext(std::string* error);

// The EGL contexts of the target engines (mesa-glsl330, mesa-es300, mesa-es100): a desktop
// core-profile 3.3 context, or an OpenGL ES context of the given major version (Mesa may give
// a later minor or major version that runs the same shaders). Null (with `error`) on failure.
enum class EglApi : uint8_t { Core33, Es3, Es2 };
std::unique_ptr<GlContext> CreateEglApiContext(EglApi api, std::string* error);

}  // namespace arbiter::runtime::exec
