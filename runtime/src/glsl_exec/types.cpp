// The table of GLSL types: see types.h.
#include "glsl_exec/types.h"

#include <array>

namespace arbiter::runtime::glsl_exec {
namespace {

constexpr std::array kTypes{
    TypeInfo{"float", GL_FLOAT, BaseKind::Float, 1, 1},
    TypeInfo{"vec2", GL_FLOAT_VEC2, BaseKind::Float, 2, 1},
    TypeInfo{"vec3", GL_FLOAT_VEC3, BaseKind::Float, 3, 1},
    TypeInfo{"vec4", GL_FLOAT_VEC4, BaseKind::Float, 4, 1},
    TypeInfo{"int", GL_INT, BaseKind::Int, 1, 1},
    TypeInfo{"ivec2", GL_INT_VEC2, BaseKind::Int, 2, 1},
    TypeInfo{"ivec3", GL_INT_VEC3, BaseKind::Int, 3, 1},
    TypeInfo{"ivec4", GL_INT_VEC4, BaseKind::Int, 4, 1},
    TypeInfo{"bool", GL_BOOL, BaseKind::Bool, 1, 1},
    TypeInfo{"bvec2", GL_BOOL_VEC2, BaseKind::Bool, 2, 1},
    TypeInfo{"bvec3", GL_BOOL_VEC3, BaseKind::Bool, 3, 1},
    TypeInfo{"bvec4", GL_BOOL_VEC4, BaseKind::Bool, 4, 1},
    TypeInfo{"mat2", GL_FLOAT_MAT2, BaseKind::Float, 4, 2},
    TypeInfo{"mat3", GL_FLOAT_MAT3, BaseKind::Float, 9, 3},
    TypeInfo{"mat4", GL_FLOAT_MAT4, BaseKind::Float, 16, 4},
    TypeInfo{"mat2x2", GL_FLOAT_MAT2, BaseKind::Float, 4, 2},
    TypeInfo{"mat2x3", GL_FLOAT_MAT2x3, BaseKind::Float, 6, 2},
    TypeInfo{"mat2x4", GL_FLOAT_MAT2x4, BaseKind::Float, 8, 2},
    TypeInfo{"mat3x2", GL_FLOAT_MAT3x2, BaseKind::Float, 6, 3},
    TypeInfo{"mat3x3", GL_FLOAT_MAT3, BaseKind::Float, 9, 3},
    TypeInfo{"mat3x4", GL_FLOAT_MAT3x4, BaseKind::Float, 12, 3},
    TypeInfo{"mat4x2", GL_FLOAT_MAT4x2, BaseKind::Float, 8, 4},
    TypeInfo{"mat4x3", GL_FLOAT_MAT4x3, BaseKind::Float, 12, 4},
    TypeInfo{"mat4x4", GL_FLOAT_MAT4, BaseKind::Float, 16, 4},
    TypeInfo{"sampler1D", GL_SAMPLER_1D, BaseKind::Sampler, 1, 1},
    TypeInfo{"sampler2D", GL_SAMPLER_2D, BaseKind::Sampler, 1, 1},
    TypeInfo{"sampler3D", GL_SAMPLER_3D, BaseKind::Sampler, 1, 1},
    TypeInfo{"samplerCube", GL_SAMPLER_CUBE, BaseKind::Sampler, 1, 1},
    TypeInfo{"sampler1DShadow", GL_SAMPLER_1D_SHADOW, BaseKind::Sampler, 1, 1},
    TypeInfo{"sampler2DShadow", GL_SAMPLER_2D_SHADOW, BaseKind::Sampler, 1, 1},
    TypeInfo{"sampler2DRect", GL_SAMPLER_2D_RECT, BaseKind::Sampler, 1, 1},
    TypeInfo{"sampler2DRectShadow", GL_SAMPLER_2D_RECT_SHADOW, BaseKind::Sampler, 1, 1},
};

}  // namespace

TypeInfo LookUpType(std::string_view name) {
  for (const TypeInfo& t : kTypes) {
    if (t.name == name) return t;
  }
  return {};
}

TypeInfo LookUpGlType(GLenum type) {
  for (const TypeInfo& t : kTypes) {
    if (t.gl_type == type) return t;
  }
  return {};
}

}  // namespace arbiter::runtime::glsl_exec
