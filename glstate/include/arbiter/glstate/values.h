// The value of every `state.*` binding of ARB programs, derived from the GL state an engine
// keeps (gl_state.h) as the specs define it: ARB_vertex_program section 2.14.3.2 (tables
// X.3.2 to X.3.8) and ARB_fragment_program section 3.11.3.2 (tables X.2.x). The reference
// interpreter reads state through these functions, so a port that feeds a translation's
// uniforms with them gets the values the interpreter computed its expectations with.
//
// Floating point: the derivations are written one operation per statement, and arbiter
// compiles its interpreter with -ffp-contract=off (no fused multiply-add, also inside GLM's
// inverse and products). A port that wants bit-identical values must compile the files that
// include this header with -ffp-contract=off too (GCC's default under -std=gnu++NN and on
// FMA targets is "fast", which fuses across statements; Clang's default fuses within one).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>
#include <map>
#include <numbers>
#include <string_view>

#include "arbiter/glstate/gl_state.h"
#include "arbiter/glstate/state_items.h"

namespace arbiter::glstate {

namespace detail {

inline constexpr Vec4 kZero{0.0f, 0.0f, 0.0f, 0.0f};

// Element `index` of a state array, or nullptr outside it.
template <typename T, size_t N>
const T* At(const std::array<T, N>& array, int32_t index) {
  if (index < 0 || static_cast<size_t>(index) >= N) return nullptr;
  return &array[static_cast<size_t>(index)];
}

// h_inf = || P + (0, 0, 1) || with P the unit vector from the eye (0,0,0,1) to the light
// position (ARBvp table X.3.3 and GL 2.0 section 2.14.1: for a light at infinity (w = 0) the
// direction of its xyz; for a local light the direction of xyz / w, which points away from
// xyz when w < 0).
inline Vec4 HalfVector(const LightState& light) {
  glm::vec3 p(light.position[0], light.position[1], light.position[2]);
  if (light.position[3] != 0.0f) p /= light.position[3];
  glm::vec3 h = glm::normalize(glm::normalize(p) + glm::vec3(0.0f, 0.0f, 1.0f));
  return {h.x, h.y, h.z, 1.0f};
}

// Light product (ARBvp table X.3.3): rgb = light colour * material colour, a = the
// material's alpha.
inline Vec4 Product(const Vec4& light, const Vec4& material) {
  return {light[0] * material[0], light[1] * material[1], light[2] * material[2], material[3]};
}

// c_scene = a_cs * a_cm + e_cm (GL 2.0 section 2.14.1), w = the diffuse material alpha
// (ARBvp table X.3.3). One operation per statement: no fused multiply-add.
inline Vec4 SceneColor(const Vec4& model_ambient, const MaterialState& material) {
  Vec4 c{};
  for (size_t i = 0; i < 3; ++i) {
    const float ambient = model_ambient[i] * material.ambient[i];
    c[i] = ambient + material.emission[i];
  }
  c[3] = material.diffuse[3];
  return c;
}

}  // namespace detail

// The matrix `matrix` names, before its modifier (ARBvp 2.14.3.2, table X.3.8): the top of
// its stack. `index` numbers the modelview, texture, palette and program matrices. Vertex
// blending (modelview[n > 0]) and the matrix palette are not part of the model: they read
// the identity, as do texture and program matrices past the model's arrays.
inline glm::mat4 BaseMatrix(const GlState& state, MatrixName matrix, int32_t index) {
  switch (matrix) {
    case MatrixName::Modelview:
      return index == 0 ? state.modelview : glm::mat4(1.0f);
    case MatrixName::Projection:
      return state.projection;
    case MatrixName::Mvp:
      // ARBvp 2.14.3.2: "MVP = P * M0".
      return state.projection * state.modelview;
    case MatrixName::Texture:
      if (const glm::mat4* m = detail::At(state.texture, index)) return *m;
      return glm::mat4(1.0f);
    case MatrixName::Palette:
      return glm::mat4(1.0f);
    case MatrixName::Program:
      if (const glm::mat4* m = detail::At(state.program, index)) return *m;
      return glm::mat4(1.0f);
  }
  return glm::mat4(1.0f);
}

// The matrix a `state.matrix.<matrix>[index]<modifier>` binding reads, column-major as GL
// and GLM hold matrices (as glUniformMatrix4fv without transpose expects): its row r is the
// binding's `.row[r]`. Inverses are GLM's; see StateUndefined for singular matrices.
inline glm::mat4 StateMatrix(const GlState& state, MatrixName matrix, int32_t index,
                             MatrixModifier modifier) {
  glm::mat4 m = BaseMatrix(state, matrix, index);
  switch (modifier) {
    case MatrixModifier::None:
      return m;
    case MatrixModifier::Inverse:
      return glm::inverse(m);
    case MatrixModifier::Transpose:
      return glm::transpose(m);
    case MatrixModifier::InvTrans:
      return glm::transpose(glm::inverse(m));
  }
  return m;
}

// The vec4 a state binding reads. Indices outside the model's arrays (lights, clip planes,
// texture units) read (0,0,0,0); a program the checker accepts never names them.
inline Vec4 StateValue(const GlState& state, const StateRef& ref) {
  const MaterialState& material = state.material[ref.face == Face::Back ? 1 : 0];
  const LightState* light = detail::At(state.light, ref.index);
  switch (ref.item) {
    case StateItem::MaterialAmbient:
      return material.ambient;
    case StateItem::MaterialDiffuse:
      return material.diffuse;
    case StateItem::MaterialSpecular:
      return material.specular;
    case StateItem::MaterialEmission:
      return material.emission;
    case StateItem::MaterialShininess:
      return {material.shininess, 0.0f, 0.0f, 1.0f};
    case StateItem::LightAmbient:
      return light ? light->ambient : detail::kZero;
    case StateItem::LightDiffuse:
      return light ? light->diffuse : detail::kZero;
    case StateItem::LightSpecular:
      return light ? light->specular : detail::kZero;
    case StateItem::LightPosition:
      return light ? light->position : detail::kZero;
    case StateItem::LightAttenuation:
      // (constant, linear, quadratic, spot exponent)
      if (!light) return detail::kZero;
      return {light->constant_attenuation, light->linear_attenuation, light->quadratic_attenuation,
              light->spot_exponent};
    case StateItem::LightSpotDirection: {
      // (direction, cos(cutoff)); the cutoff is in degrees (180: cos = -1).
      if (!light) return detail::kZero;
      const float radians = light->spot_cutoff * (std::numbers::pi_v<float> / 180.0f);
      return {light->spot_direction[0], light->spot_direction[1], light->spot_direction[2],
              std::cos(radians)};
    }
    case StateItem::LightHalf:
      return light ? detail::HalfVector(*light) : detail::kZero;
    case StateItem::LightModelAmbient:
      return state.light_model_ambient;
    case StateItem::LightModelSceneColor:
      return detail::SceneColor(state.light_model_ambient, material);
    case StateItem::LightProdAmbient:
      return light ? detail::Product(light->ambient, material.ambient) : detail::kZero;
    case StateItem::LightProdDiffuse:
      return light ? detail::Product(light->diffuse, material.diffuse) : detail::kZero;
    case StateItem::LightProdSpecular:
      return light ? detail::Product(light->specular, material.specular) : detail::kZero;
    case StateItem::TexGenEye:
    case StateItem::TexGenObject: {
      const TexGenState* texgen = detail::At(state.texgen, ref.index);
      if (!texgen || ref.coord > 3) return detail::kZero;
      const auto& planes = ref.item == StateItem::TexGenEye ? texgen->eye : texgen->object;
      return planes[ref.coord];
    }
    case StateItem::FogColor:
      return state.fog_color;
    case StateItem::FogParams: {
      // (density, start, end, 1 / (end - start))
      const float range = state.fog_end - state.fog_start;
      return {state.fog_density, state.fog_start, state.fog_end, 1.0f / range};
    }
    case StateItem::ClipPlane: {
      const Vec4* plane = detail::At(state.clip_plane, ref.index);
      return plane ? *plane : detail::kZero;
    }
    case StateItem::PointSize:
      // (size, min, max, fade threshold)
      return {state.point_size, state.point_size_min, state.point_size_max,
              state.point_fade_threshold};
    case StateItem::PointAttenuation:
      return {state.point_attenuation[0], state.point_attenuation[1], state.point_attenuation[2],
              1.0f};
    case StateItem::TexEnvColor: {
      const Vec4* color = detail::At(state.texenv_color, ref.index);
      return color ? *color : detail::kZero;
    }
    case StateItem::DepthRange:
      // (near, far, far - near, 1)
      return {state.depth_near, state.depth_far, state.depth_far - state.depth_near, 1.0f};
    case StateItem::MatrixRow: {
      // ARB reads ROWS; GLM (like GL) stores columns: row r = (m[0][r], m[1][r], ...).
      const glm::mat4 m = StateMatrix(state, ref.matrix, ref.index, ref.modifier);
      const int r = ref.row & 3;
      return {m[0][r], m[1][r], m[2][r], m[3][r]};
    }
  }
  return detail::kZero;
}

// Why the specs leave the value of a state binding undefined, or "" when they define it.
// ARBvp 2.14.3.2: "If the specified matrix is poorly-conditioned (singular or nearly so), its
// inverse matrix is undefined." Only exact singularity (or a non-finite determinant) is
// flagged: "nearly" has no threshold in the spec.
inline std::string_view StateUndefined(const GlState& state, const StateRef& ref) {
  if (ref.item != StateItem::MatrixRow) return {};
  if (ref.modifier != MatrixModifier::Inverse && ref.modifier != MatrixModifier::InvTrans) {
    return {};
  }
  const float det = glm::determinant(BaseMatrix(state, ref.matrix, ref.index));
  if (det == 0.0f || !std::isfinite(det)) return "the inverse of a singular matrix";
  return {};
}

// program.env[index] or program.local[index] from one of ProgramParameters' maps: (0,0,0,0)
// where the map has no entry, GL's initial value.
inline Vec4 ParameterValue(const std::map<int, Vec4>& params, int32_t index) {
  const auto it = params.find(index);
  return it == params.end() ? detail::kZero : it->second;
}

}  // namespace arbiter::glstate
