// Loading the GL entry points through OSMesaGetProcAddress.
#include "gl_api.h"

#include "osmesa_library.h"

namespace arbiter::runtime {
namespace {

// Loads one entry point; false (naming it in `error`) when OSMesa does not know it.
template <typename Fn>
bool Load(Fn* fn, const char* name, std::string* error) {
  const OsMesaLibrary* lib = LoadOsMesa(error);
  if (lib == nullptr) return false;
  OSMESAproc proc = lib->GetProcAddress(name);
  if (proc == nullptr) {
    *error = std::string("OSMesaGetProcAddress does not know '") + name + "'";
    return false;
  }
  *fn = reinterpret_cast<Fn>(proc);
  return true;
}

}  // namespace

bool LoadGlApi(GlApi* api, std::string* error) {
  return Load(&api->GetError, "glGetError", error) &&
         Load(&api->GetIntegerv, "glGetIntegerv", error) &&
         Load(&api->GetString, "glGetString", error) &&
         Load(&api->CreateShader, "glCreateShader", error) &&
         Load(&api->ShaderSource, "glShaderSource", error) &&
         Load(&api->CompileShader, "glCompileShader", error) &&
         Load(&api->GetShaderiv, "glGetShaderiv", error) &&
         Load(&api->GetShaderInfoLog, "glGetShaderInfoLog", error) &&
         Load(&api->DeleteShader, "glDeleteShader", error) &&
         Load(&api->CreateProgram, "glCreateProgram", error) &&
         Load(&api->AttachShader, "glAttachShader", error) &&
         Load(&api->LinkProgram, "glLinkProgram", error) &&
         Load(&api->GetProgramiv, "glGetProgramiv", error) &&
         Load(&api->GetProgramInfoLog, "glGetProgramInfoLog", error) &&
         Load(&api->DeleteProgram, "glDeleteProgram", error) &&
         Load(&api->GenProgramsARB, "glGenProgramsARB", error) &&
         Load(&api->DeleteProgramsARB, "glDeleteProgramsARB", error) &&
         Load(&api->BindProgramARB, "glBindProgramARB", error) &&
         Load(&api->ProgramStringARB, "glProgramStringARB", error) &&
         Load(&api->GetProgramivARB, "glGetProgramivARB", error);
}

}  // namespace arbiter::runtime
