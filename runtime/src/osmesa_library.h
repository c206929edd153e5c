// libOSMesa loaded on first use (dlopen), so that arbiter starts without loading Mesa and
// LLVM: a single-file check of an ARB program must not pay Mesa's start-up.
#pragma once

#include <GL/osmesa.h>

#include <string>

namespace arbiter::runtime {

// The OSMesa entry points arbiter uses.
struct OsMesaLibrary {
  OSMesaContext (*CreateContextAttribs)(const int*, OSMesaContext) = nullptr;
  GLboolean (*MakeCurrent)(OSMesaContext, void*, GLenum, GLsizei, GLsizei) = nullptr;
  void (*DestroyContext)(OSMesaContext) = nullptr;
  OSMESAproc (*GetProcAddress)(const char*) = nullptr;
};

// Loads libOSMesa once per process; null (and `error` set) when it cannot be loaded.
const OsMesaLibrary* LoadOsMesa(std::string* error);

// A compatibility-profile RGBA context without depth, stencil or accumulation buffers (what
// every arbiter context is; rendering goes to framebuffer objects); null on failure.
OSMesaContext CreateCompatibilityContext(const OsMesaLibrary& lib);

}  // namespace arbiter::runtime
