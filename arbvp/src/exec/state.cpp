// The GL state model: initial values, the state.* bindings as the ARB specs define them
// (ARBvp 2.14.3.2 tables X.3.2-X.3.8, ARBfp 3.11.3.2), and the stable order of results.
#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <numbers>

#include "arbiter/arbvp/exec.h"
#include "exec/state_internal.h"

namespace arbiter::arbvp {

GlState::GlState() {
  // glm 0.9.9 leaves default-constructed matrices uninitialised: GL's initial value of every
  // matrix stack is the identity.
  modelview = glm::mat4(1.0f);
  projection = glm::mat4(1.0f);
  texture.fill(glm::mat4(1.0f));
  program.fill(glm::mat4(1.0f));
  // OpenGL 2.0 table 6.x: light 0 starts with white diffuse and specular colours.
  light[0].diffuse = {1.0f, 1.0f, 1.0f, 1.0f};
  light[0].specular = {1.0f, 1.0f, 1.0f, 1.0f};
}

VertexInput::VertexInput() {
  texcoord.fill(Vec4{0.0f, 0.0f, 0.0f, 1.0f});
  generic.fill(Vec4{0.0f, 0.0f, 0.0f, 1.0f});
}

FragmentInput::FragmentInput() { texcoord.fill(Vec4{0.0f, 0.0f, 0.0f, 1.0f}); }

namespace {

constexpr Vec4 kZero{0.0f, 0.0f, 0.0f, 0.0f};

template <typename T, size_t N>
const T* At(const std::array<T, N>& array, int32_t index) {
  if (index < 0 || static_cast<size_t>(index) >= N) return nullptr;
  return &array[static_cast<size_t>(index)];
}

// The matrix a MatrixRow binding selects, before its modifier. Vertex blending
// (modelview[n > 0]) and the matrix palette are not part of the model: they read the
// identity (the checker rejects them under the builtin profiles).
glm::mat4 BaseMatrix(const GlState& state, const Binding& b) {
  switch (b.matrix) {
    case MatrixName::Modelview:
      return b.index == 0 ? state.modelview : glm::mat4(1.0f);
    case MatrixName::Projection:
      return state.projection;
    case MatrixName::Mvp:
      // ARBvp 2.14.3.2: "MVP = P * M0".
      return state.projection * state.modelview;
    case MatrixName::Texture:
      if (const glm::mat4* m = At(state.texture, b.index)) return *m;
      return glm::mat4(1.0f);
    case MatrixName::Palette:
      return glm::mat4(1.0f);
    case MatrixName::Program:
      if (const glm::mat4* m = At(state.program, b.index)) return *m;
      return glm::mat4(1.0f);
  }
  return glm::mat4(1.0f);
}

glm::mat4 SelectedMatrix(const GlState& state, const Binding& b) {
  glm::mat4 m = BaseMatrix(state, b);
  switch (b.modifier) {
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

// h_inf = || P + (0, 0, 1) || with P the unit vector from the eye (0,0,0,1) to the light
// position (ARBvp table X.3.3 and GL 2.0 section 2.14.1: for a light at infinity (w = 0) the
// direction of its xyz; for a local light the direction of xyz / w, which points away from
// xyz when w < 0).
Vec4 HalfVector(const LightState& light) {
  glm::vec3 p(light.position[0], light.position[1], light.position[2]);
  if (light.position[3] != 0.0f) p /= light.position[3];
  glm::vec3 h = glm::normalize(glm::normalize(p) + glm::vec3(0.0f, 0.0f, 1.0f));
  return {h.x, h.y, h.z, 1.0f};
}

// Light product: rgb = light colour * material colour, a = the material's alpha.
Vec4 Product(const Vec4& light, const Vec4& material) {
  return {light[0] * material[0], light[1] * material[1], light[2] * material[2], material[3]};
}

}  // namespace

Vec4 ReadStateBinding(const GlState& state, const Binding& b) {
  const MaterialState& material = state.material[b.face == Face::Back ? 1 : 0];
  const LightState* light = At(state.light, b.index);
  switch (b.state) {
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
      return light ? light->ambient : kZero;
    case StateItem::LightDiffuse:
      return light ? light->diffuse : kZero;
    case StateItem::LightSpecular:
      return light ? light->specular : kZero;
    case StateItem::LightPosition:
      return light ? light->position : kZero;
    case StateItem::LightAttenuation:
      // (constant, linear, quadratic, spot exponent)
      if (!light) return kZero;
      return {light->constant_attenuation, light->linear_attenuation, light->quadratic_attenuation,
              light->spot_exponent};
    case StateItem::LightSpotDirection: {
      // (direction, cos(cutoff)); the cutoff is in degrees (180: cos = -1).
      if (!light) return kZero;
      float radians = light->spot_cutoff * (std::numbers::pi_v<float> / 180.0f);
      return {light->spot_direction[0], light->spot_direction[1], light->spot_direction[2],
              std::cos(radians)};
    }
    case StateItem::LightHalf:
      return light ? HalfVector(*light) : kZero;
    case StateItem::LightModelAmbient:
      return state.light_model_ambient;
    case StateItem::LightModelSceneColor: {
      // c_scene = a_cs * a_cm + e_cm; w = the diffuse material alpha.
      const Vec4& a = state.light_model_ambient;
      return {a[0] * material.ambient[0] + material.emission[0],
              a[1] * material.ambient[1] + material.emission[1],
              a[2] * material.ambient[2] + material.emission[2], material.diffuse[3]};
    }
    case StateItem::LightProdAmbient:
      return light ? Product(light->ambient, material.ambient) : kZero;
    case StateItem::LightProdDiffuse:
      return light ? Product(light->diffuse, material.diffuse) : kZero;
    case StateItem::LightProdSpecular:
      return light ? Product(light->specular, material.specular) : kZero;
    case StateItem::TexGenEye:
    case StateItem::TexGenObject: {
      const TexGenState* texgen = At(state.texgen, b.index);
      if (!texgen || b.coord > 3) return kZero;
      const auto& planes = b.state == StateItem::TexGenEye ? texgen->eye : texgen->object;
      return planes[b.coord];
    }
    case StateItem::FogColor:
      return state.fog_color;
    case StateItem::FogParams:
      // (density, start, end, 1 / (end - start))
      return {state.fog_density, state.fog_start, state.fog_end,
              1.0f / (state.fog_end - state.fog_start)};
    case StateItem::ClipPlane: {
      const Vec4* plane = At(state.clip_plane, b.index);
      return plane ? *plane : kZero;
    }
    case StateItem::PointSize:
      // (size, min, max, fade threshold)
      return {state.point_size, state.point_size_min, state.point_size_max,
              state.point_fade_threshold};
    case StateItem::PointAttenuation:
      return {state.point_attenuation[0], state.point_attenuation[1], state.point_attenuation[2],
              1.0f};
    case StateItem::TexEnvColor: {
      const Vec4* color = At(state.texenv_color, b.index);
      return color ? *color : kZero;
    }
    case StateItem::DepthRange:
      // (near, far, far - near, 1)
      return {state.depth_near, state.depth_far, state.depth_far - state.depth_near, 1.0f};
    case StateItem::MatrixRow: {
      // ARB reads ROWS; glm (like GL) stores columns: row r = (m[0][r], m[1][r], ...).
      glm::mat4 m = SelectedMatrix(state, b);
      int r = b.row & 3;
      return {m[0][r], m[1][r], m[2][r], m[3][r]};
    }
  }
  return kZero;
}

std::string StateBindingUndefined(const GlState& state, const Binding& b) {
  if (b.kind != BindingKind::State || b.state != StateItem::MatrixRow) return {};
  if (b.modifier != MatrixModifier::Inverse && b.modifier != MatrixModifier::InvTrans) return {};
  // ARBvp 2.14.3.2: "If the specified matrix is poorly-conditioned (singular or nearly so),
  // its inverse matrix is undefined." Only exact singularity is flagged: "nearly" has no
  // threshold in the spec.
  float det = glm::determinant(BaseMatrix(state, b));
  if (det == 0.0f || !std::isfinite(det)) return "the inverse of a singular matrix";
  return {};
}

namespace {

// Rank of a result register in the stable order; ties are broken by index.
int ResultRank(const Binding& b) {
  switch (b.result) {
    case ResultReg::Position:
      return 0;
    case ResultReg::Color:
      return 1 + (b.face == Face::Back ? 2 : 0) + (b.secondary ? 1 : 0);
    case ResultReg::FogCoord:
      return 5;
    case ResultReg::PointSize:
      return 6;
    case ResultReg::TexCoord:
      return 7;
    case ResultReg::ClipDistance:
      return 8;
    case ResultReg::FragColor:
      return 9;
    case ResultReg::FragDepth:
      return 10;
  }
  return 11;
}

}  // namespace

bool ResultRegOrder(const Binding& a, const Binding& b) {
  int ra = ResultRank(a);
  int rb = ResultRank(b);
  if (ra != rb) return ra < rb;
  return a.index < b.index;
}

}  // namespace arbiter::arbvp
