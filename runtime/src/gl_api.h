// The GL entry points the runtime calls, all loaded through OSMesaGetProcAddress.
#pragma once

#include <GL/osmesa.h>

#include <string>

namespace arbiter::runtime {

// Core GL 1.x entry points, declared by hand: nothing may refer to libGL's symbols (linking
// libGL beside libOSMesa makes glvnd's glGetString win and return NULL: docs/design/platform.md).
using PfnGetError = GLenum(APIENTRYP)();
using PfnGetIntegerv = void(APIENTRYP)(GLenum, GLint*);
using PfnGetString = const GLubyte*(APIENTRYP)(GLenum);

struct GlApi {
  PfnGetError GetError = nullptr;
  PfnGetIntegerv GetIntegerv = nullptr;
  PfnGetString GetString = nullptr;
  // GL 2.0 shader objects.
  PFNGLCREATESHADERPROC CreateShader = nullptr;
  PFNGLSHADERSOURCEPROC ShaderSource = nullptr;
  PFNGLCOMPILESHADERPROC CompileShader = nullptr;
  PFNGLGETSHADERIVPROC GetShaderiv = nullptr;
  PFNGLGETSHADERINFOLOGPROC GetShaderInfoLog = nullptr;
  PFNGLDELETESHADERPROC DeleteShader = nullptr;
  PFNGLCREATEPROGRAMPROC CreateProgram = nullptr;
  PFNGLATTACHSHADERPROC AttachShader = nullptr;
  PFNGLLINKPROGRAMPROC LinkProgram = nullptr;
  PFNGLGETPROGRAMIVPROC GetProgramiv = nullptr;
  PFNGLGETPROGRAMINFOLOGPROC GetProgramInfoLog = nullptr;
  PFNGLDELETEPROGRAMPROC DeleteProgram = nullptr;
  // ARB_vertex_program / ARB_fragment_program.
  PFNGLGENPROGRAMSARBPROC GenProgramsARB = nullptr;
  PFNGLDELETEPROGRAMSARBPROC DeleteProgramsARB = nullptr;
  PFNGLBINDPROGRAMARBPROC BindProgramARB = nullptr;
  PFNGLPROGRAMSTRINGARBPROC ProgramStringARB = nullptr;
  PFNGLGETPROGRAMIVARBPROC GetProgramivARB = nullptr;
};

// Loads every entry point of `api`. On failure returns false and names the missing one in
// `error`.
[[nodiscard]] bool LoadGlApi(GlApi* api, std::string* error);

}  // namespace arbiter::runtime
