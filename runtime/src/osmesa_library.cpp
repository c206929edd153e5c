// libOSMesa loaded on first use (dlopen): see osmesa_library.h.
#include "osmesa_library.h"

#include <dlfcn.h>

#include <mutex>

namespace arbiter::runtime {
namespace {

template <typename Fn>
bool Resolve(void* handle, const char* name, Fn* fn) {
  void* symbol = dlsym(handle, name);
  if (symbol == nullptr) return false;
  *fn = reinterpret_cast<Fn>(symbol);
  return true;
}

}  // namespace

const OsMesaLibrary* LoadOsMesa(std::string* error) {
  static OsMesaLibrary library;
  static std::string load_error;
  static std::once_flag once;
  std::call_once(once, [] {
    void* handle = nullptr;
    for (const char* name : {"libOSMesa.so.8", "libOSMesa.so"}) {
      handle = dlopen(name, RTLD_NOW | RTLD_LOCAL);
      if (handle != nullptr) break;
    }
    if (handle == nullptr) {
      const char* why = dlerror();
      load_error = std::string("cannot load libOSMesa: ") + (why ? why : "not found") +
                   " (install Debian's libosmesa6)";
      return;
    }
    // The library stays loaded for the life of the process, as the contexts need it.
    if (!Resolve(handle, "OSMesaCreateContextAttribs", &library.CreateContextAttribs) ||
        !Resolve(handle, "OSMesaMakeCurrent", &library.MakeCurrent) ||
        !Resolve(handle, "OSMesaDestroyContext", &library.DestroyContext) ||
        !Resolve(handle, "OSMesaGetProcAddress", &library.GetProcAddress)) {
      load_error = "libOSMesa lacks an entry point arbiter needs";
      library = OsMesaLibrary{};
    }
  });
  if (library.GetProcAddress == nullptr) {
    *error = load_error;
    return nullptr;
  }
  return &library;
}

OSMesaContext CreateCompatibilityContext(const OsMesaLibrary& lib) {
  const int attribs[] = {OSMESA_FORMAT,
                         OSMESA_RGBA,
                         OSMESA_DEPTH_BITS,
                         0,
                         OSMESA_STENCIL_BITS,
                         0,
                         OSMESA_ACCUM_BITS,
                         0,
                         OSMESA_PROFILE,
                         OSMESA_COMPAT_PROFILE,
                         0};
  return lib.CreateContextAttribs(attribs, nullptr);
}

}  // namespace arbiter::runtime
