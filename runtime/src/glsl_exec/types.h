// GLSL 1.10/1.20 types as the GLSL exec needs them: how many numbers a type holds, and the
// GL enums glGetActiveUniform and glGetTransformFeedbackVarying answer with.
#pragma once

#include <GL/gl.h>
#include <GL/glext.h>

#include <string>
#include <string_view>

namespace arbiter::runtime::glsl_exec {

enum class BaseKind : uint8_t { Float, Int, Bool, Sampler };

struct TypeInfo {
  std::string_view name;  // "vec3", "mat2x3", "sampler2D"
  GLenum gl_type = 0;     // GL_FLOAT_VEC3, ...
  BaseKind base = BaseKind::Float;
  int components = 0;  // numbers one value holds (mat3: 9); 0: unknown type
  int columns = 1;     // matrices: columns (each of components / columns rows)
};

// By GLSL name; components 0 when unknown.
TypeInfo LookUpType(std::string_view name);
// By GL enum; components 0 when unknown.
TypeInfo LookUpGlType(GLenum type);

}  // namespace arbiter::runtime::glsl_exec
