// Uniform values by name: what a port feeds each uniform of a translated ARB program, given
// the ARB spelling the translation's binding map lists for it ("state.light[1].half",
// "state.matrix.program[0].inverse", "program.env[3]") and the GL state the engine keeps.
// See docs/glstate.md; the floating-point note of values.h applies.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "arbiter/glstate/gl_state.h"
#include "arbiter/glstate/spelling.h"
#include "arbiter/glstate/state_items.h"
#include "arbiter/glstate/values.h"

namespace arbiter::glstate {

enum class UniformType : uint8_t { Vector, Matrix };  // vec4, mat4

// One uniform's value, ready for glUniform4fv (Vector: data[0..3]) or glUniformMatrix4fv with
// transpose GL_FALSE (Matrix: column-major, data[4 * c + r] is row r of column c, so that the
// matrix's rows are the ARB rows state.matrix.<m>.row[r]).
struct UniformData {
  UniformType type = UniformType::Vector;
  std::array<float, 16> data{};
};

namespace detail {

// Whether the selector `ref` spells lies within the model's arrays.
inline bool InModel(const StateRef& ref) {
  if (ref.index < 0) return false;
  if (ref.item == StateItem::MatrixRow) {
    switch (ref.matrix) {
      case MatrixName::Texture:
        return ref.index < kMaxTextureCoords;
      case MatrixName::Program:
        return ref.index < kMaxProgramMatrices;
      default:
        return true;  // modelview[n > 0] and the palette read the identity (values.h)
    }
  }
  const StateGroupInfo* group = FindStateGroup(GetStateItemInfo(ref.item).group);
  switch (group ? group->selector : StateSelector::None) {
    case StateSelector::None:
      return true;
    case StateSelector::Light:
      return ref.index < kMaxLights;
    case StateSelector::ClipPlane:
      return ref.index < kMaxClipPlanes;
    case StateSelector::TexCoordUnit:
    case StateSelector::TexImageUnit:
      return ref.index < kMaxTextureCoords;
  }
  return false;
}

inline UniformData MatrixUniform(const glm::mat4& m) {
  UniformData out;
  out.type = UniformType::Matrix;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) out.data[static_cast<size_t>(4 * c + r)] = m[c][r];
  }
  return out;
}

inline UniformData VectorUniform(const Vec4& v) {
  UniformData out;
  for (size_t i = 0; i < 4; ++i) out.data[i] = v[i];
  return out;
}

}  // namespace detail

// How a shadow lookup's result r expands under GL_DEPTH_TEXTURE_MODE `mode`, per component:
// 0 reads 0, 1 reads r, 2 reads 1. LUMINANCE (r, r, r, 1), INTENSITY (r, r, r, r), ALPHA
// (0, 0, 0, r), RED (r, 0, 0, 1); an unknown mode reads as LUMINANCE, GL's initial value.
inline Vec4 DepthModeSelector(uint32_t mode) {
  switch (mode) {
    case kDepthModeIntensity:
      return {1, 1, 1, 1};
    case kDepthModeAlpha:
      return {0, 0, 0, 1};
    case kDepthModeRed:
      return {1, 0, 0, 2};
    default:
      return {1, 1, 1, 2};
  }
}

// The value of the uniform whose binding is spelled `spelling`:
//   a state binding ("state.fog.params", "state.matrix.mvp.row[0]"): StateValue, a Vector;
//   a whole matrix ("state.matrix.modelview[0].inverse"): StateMatrix, a Matrix;
//   "program.env[n]" / "program.local[n]": that entry of `params`, the parameters of the
//   program the uniform belongs to (env of its target, local of the program), a Vector;
//   three spellings that are not ARB bindings, for what the translations emulate:
//   "texture[n].depthmode", DepthModeSelector of unit n's GL_DEPTH_TEXTURE_MODE (shadow
//   lookups), "framebuffer.height", (height, 0, 0, 0) (fragment.position), and
//   "clip[n].enabled", (1 or 0, 0, 0, 0) (user clip planes), Vectors.
// False, leaving `out` alone, when the spelling is not canonical (spelling.h) or names an
// index past the model's arrays (gl_state.h: lights, clip planes, texture units, texture and
// program matrices, kMaxProgramParams parameters).
[[nodiscard]] inline bool UniformValue(const GlState& state, const ProgramParameters& params,
                                       std::string_view spelling, UniformData* out) {
  StateRef ref;
  if (ParseStateSpelling(spelling, &ref)) {
    if (!detail::InModel(ref)) return false;
    *out = detail::VectorUniform(StateValue(state, ref));
    return true;
  }
  MatrixRef matrix;
  if (ParseMatrixSpelling(spelling, &matrix)) {
    ref.item = StateItem::MatrixRow;
    ref.matrix = matrix.matrix;
    ref.index = matrix.index;
    if (!detail::InModel(ref)) return false;
    *out = detail::MatrixUniform(StateMatrix(state, matrix.matrix, matrix.index, matrix.modifier));
    return true;
  }
  if (spelling == "framebuffer.height") {
    *out = detail::VectorUniform({state.framebuffer_height, 0.0f, 0.0f, 0.0f});
    return true;
  }
  StateRef plane;
  if (detail::MatchSpelling({"clip[{i}].enabled"}, spelling, &plane)) {
    if (plane.index < 0 || plane.index >= kMaxClipPlanes) return false;
    const bool on = state.clip_enabled[static_cast<size_t>(plane.index)];
    *out = detail::VectorUniform({on ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f});
    return true;
  }
  StateRef unit;
  if (detail::MatchSpelling({"texture[{i}].depthmode"}, spelling, &unit)) {
    if (unit.index < 0 || unit.index >= kMaxTextureImageUnits) return false;
    *out = detail::VectorUniform(DepthModeSelector(state.depth_texture_mode[unit.index]));
    return true;
  }
  for (const bool local : {false, true}) {
    StateRef param;
    if (!detail::MatchSpelling({local ? "program.local[{i}]" : "program.env[{i}]"}, spelling,
                               &param)) {
      continue;
    }
    if (param.index >= kMaxProgramParams) return false;
    *out = detail::VectorUniform(ParameterValue(local ? params.local : params.env, param.index));
    return true;
  }
  return false;
}

}  // namespace arbiter::glstate
