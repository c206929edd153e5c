// The executor's EGL context: libEGL opened with dlopen (never linked, like OSMesa), the
// surfaceless Mesa platform, a compatibility-profile desktop GL context without a surface
// (drawing goes to a framebuffer object).
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>
#include <fmt/format.h>

#include <mutex>

#include "exec/context.h"

namespace arbiter::runtime::exec {
namespace {

struct EglLibrary {
  PFNEGLGETPROCADDRESSPROC GetProcAddress = nullptr;
  PFNEGLGETERRORPROC GetError = nullptr;
  PFNEGLINITIALIZEPROC Initialize = nullptr;
  PFNEGLBINDAPIPROC BindAPI = nullptr;
  PFNEGLCREATECONTEXTPROC CreateContext = nullptr;
  PFNEGLDESTROYCONTEXTPROC DestroyContext = nullptr;
  PFNEGLMAKECURRENTPROC MakeCurrent = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC GetPlatformDisplayEXT = nullptr;
  EGLDisplay display = EGL_NO_DISPLAY;
};

template <typename Fn>
bool Resolve(void* handle, const char* name, Fn* fn) {
  void* symbol = dlsym(handle, name);
  if (symbol == nullptr) return false;
  *fn = reinterpret_cast<Fn>(symbol);
  return true;
}

// Opens libEGL and initialises the surfaceless display once per process; the display stays
// initialised for the life of the process (eglTerminate would end every context on it).
const EglLibrary* LoadEgl(std::string* error) {
  static EglLibrary library;
  static std::string load_error;
  static std::once_flag once;
  std::call_once(once, [] {
    void* handle = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* why = dlerror();
      load_error = std::string("cannot load libEGL: ") + (why ? why : "not found") +
                   " (install Debian's libegl1 and libegl-mesa0)";
      return;
    }
    EglLibrary lib;
    if (!Resolve(handle, "eglGetProcAddress", &lib.GetProcAddress) ||
        !Resolve(handle, "eglGetError", &lib.GetError) ||
        !Resolve(handle, "eglInitialize", &lib.Initialize) ||
        !Resolve(handle, "eglBindAPI", &lib.BindAPI) ||
        !Resolve(handle, "eglCreateContext", &lib.CreateContext) ||
        !Resolve(handle, "eglDestroyContext", &lib.DestroyContext) ||
        !Resolve(handle, "eglMakeCurrent", &lib.MakeCurrent)) {
      load_error = "libEGL lacks an entry point arbiter needs";
      return;
    }
    lib.GetPlatformDisplayEXT = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        lib.GetProcAddress("eglGetPlatformDisplayEXT"));
    if (lib.GetPlatformDisplayEXT == nullptr) {
      load_error = "libEGL lacks eglGetPlatformDisplayEXT (EGL_EXT_platform_base)";
      return;
    }
    lib.display =
        lib.GetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (lib.display == EGL_NO_DISPLAY) {
      load_error = fmt::format("no EGL surfaceless display (EGL error 0x{:04x})", lib.GetError());
      return;
    }
    EGLint major = 0;
    EGLint minor = 0;
    if (lib.Initialize(lib.display, &major, &minor) != EGL_TRUE) {
      load_error = fmt::format("eglInitialize failed (EGL error 0x{:04x})", lib.GetError());
      return;
    }
    library = lib;
  });
  if (library.display == EGL_NO_DISPLAY) {
    *error = load_error;
    return nullptr;
  }
  return &library;
}

class EglGlContext final : public GlContext {
 public:
  EglGlContext(const EglLibrary* lib, EGLContext context, EGLenum api = EGL_OPENGL_API)
      : lib_(lib), context_(context), api_(api) {}
  ~EglGlContext() override { lib_->DestroyContext(lib_->display, context_); }
  EglGlContext(const EglGlContext&) = delete;
  EglGlContext& operator=(const EglGlContext&) = delete;

  bool MakeCurrent() override {
    return lib_->BindAPI(api_) == EGL_TRUE &&
           lib_->MakeCurrent(lib_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) == EGL_TRUE;
  }
  void Release() override {
    lib_->MakeCurrent(lib_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  GetProcFn get_proc() const override {
    const EglLibrary* lib = lib_;
    return [lib](const char* name) { return reinterpret_cast<GlProc>(lib->GetProcAddress(name)); };
  }

 private:
  const EglLibrary* lib_;
  EGLContext context_;
  EGLenum api_;
};

}  // namespace

std::unique_ptr<GlContext> CreateEglContext(std::string* error) {
  const EglLibrary* lib = LoadEgl(error);
  if (lib == nullptr) return nullptr;
  if (lib->BindAPI(EGL_OPENGL_API) != EGL_TRUE) {
    *error = "eglBindAPI(EGL_OPENGL_API) failed: desktop GL is not available through EGL";
    return nullptr;
  }
  const EGLint attribs[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK,
                            EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
  EGLContext context = lib->CreateContext(lib->display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
  if (context == EGL_NO_CONTEXT) {
    *error = fmt::format("eglCreateContext failed (compatibility profile, EGL error 0x{:04x})",
                         lib->GetError());
    return nullptr;
  }
  return std::make_unique<EglGlContext>(lib, context);
}

std::unique_ptr<GlContext> CreateEglApiContext(EglApi api, std::string* error) {
  const EglLibrary* lib = LoadEgl(error);
  if (lib == nullptr) return nullptr;
  const bool es = api != EglApi::Core33;
  const EGLenum client = es ? EGL_OPENGL_ES_API : EGL_OPENGL_API;
  const char* what = api == EglApi::Core33 ? "OpenGL 3.3 core profile"
                     : api == EglApi::Es3  ? "OpenGL ES 3.0"
                                           : "OpenGL ES 2.0";
  if (lib->BindAPI(client) != EGL_TRUE) {
    *error = fmt::format("eglBindAPI failed: {} is not available through EGL", what);
    return nullptr;
  }
  const EGLint core[] = {EGL_CONTEXT_MAJOR_VERSION,
                         3,
                         EGL_CONTEXT_MINOR_VERSION,
                         3,
                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                         EGL_NONE};
  const EGLint gles[] = {EGL_CONTEXT_MAJOR_VERSION, api == EglApi::Es3 ? 3 : 2, EGL_NONE};
  EGLContext context =
      lib->CreateContext(lib->display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, es ? gles : core);
  if (context == EGL_NO_CONTEXT) {
    *error = fmt::format("eglCreateContext failed ({}, EGL error 0x{:04x})", what, lib->GetError());
    return nullptr;
  }
  return std::make_unique<EglGlContext>(lib, context, client);
}

}  // namespace arbiter::runtime::exec
