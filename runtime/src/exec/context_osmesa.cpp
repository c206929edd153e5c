// The executor's OSMesa context: libOSMesa through osmesa_library.h, compatibility profile,
// a small unused window buffer (drawing goes to a framebuffer object).
#include <GL/osmesa.h>

#include <cstdlib>
#include <vector>

#include "exec/context.h"
#include "osmesa_library.h"

namespace arbiter::runtime::exec {
namespace {

constexpr GLsizei kWindowSize = 4;

class OsMesaGlContext final : public GlContext {
 public:
  OsMesaGlContext(const OsMesaLibrary* lib, OSMesaContext context)
      : lib_(lib), context_(context), buffer_(kWindowSize * kWindowSize * 4) {}
  ~OsMesaGlContext() override { lib_->DestroyContext(context_); }
  OsMesaGlContext(const OsMesaGlContext&) = delete;
  OsMesaGlContext& operator=(const OsMesaGlContext&) = delete;

  bool MakeCurrent() override {
    return lib_->MakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kWindowSize,
                             kWindowSize) == GL_TRUE;
  }
  void Release() override { lib_->MakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0); }
  GetProcFn get_proc() const override {
    const OsMesaLibrary* lib = lib_;
    return [lib](const char* name) { return reinterpret_cast<GlProc>(lib->GetProcAddress(name)); };
  }

 private:
  const OsMesaLibrary* lib_;
  OSMesaContext context_;
  std::vector<GLubyte> buffer_;
};

}  // namespace

void SetMesaEnvironment(const std::string& driver) {
  setenv("GALLIUM_DRIVER", driver.c_str(), 1);
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  // EGL would otherwise pick a hardware driver where a GPU exists: only softpipe and
  // llvmpipe are supported.
  setenv("LIBGL_ALWAYS_SOFTWARE", "true", 1);
}

void PreloadOsMesa() {
  std::string ignored;  // a worker that needs the library reports the error itself
  LoadOsMesa(&ignored);
}

std::unique_ptr<GlContext> CreateOsMesaContext(std::string* error) {
  const OsMesaLibrary* lib = LoadOsMesa(error);
  if (lib == nullptr) return nullptr;
  OSMesaContext context = CreateCompatibilityContext(*lib);
  if (context == nullptr) {
    *error = "OSMesaCreateContextAttribs failed (compatibility profile)";
    return nullptr;
  }
  return std::make_unique<OsMesaGlContext>(lib, context);
}

}  // namespace arbiter::runtime::exec
