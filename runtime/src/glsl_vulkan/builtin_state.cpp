// The built-in uniform state's values: see builtin_state.h. One table, from each built-in
// (and member) to the ARB spelling glstate evaluates and the part of its value GLSL takes.
#include "glsl_vulkan/builtin_state.h"

#include <fmt/format.h>

#include <cmath>

#include "arbiter/glstate/uniforms.h"

namespace arbiter::runtime::glsl_vulkan {
namespace {

// What a built-in takes of the value of its spelling: a whole vec4 or mat4, one component,
// the first three, or the upper-left 3x3 of a matrix.
enum class Part : uint8_t { Whole, X, Y, Z, W, Xyz, Mat3 };

struct StateEntry {
  std::string_view base;      // "gl_LightSource"
  std::string_view member;    // "spotExponent", "" for the whole variable
  std::string_view spelling;  // ARB spelling; {i}: the array index, {f}: front or back
  Part part;
};

// GLSL 1.10 7.5 against ARB_vertex_program 2.14.3.2 (tables X.2.x), as Mesa's GLSL compiler
// maps the built-ins to the same state (src/compiler/glsl/builtin_variables.cpp).
constexpr StateEntry kState[] = {
    {"gl_ModelViewMatrix", "", "state.matrix.modelview[0]", Part::Whole},
    {"gl_ModelViewMatrixInverse", "", "state.matrix.modelview[0].inverse", Part::Whole},
    {"gl_ModelViewMatrixTranspose", "", "state.matrix.modelview[0].transpose", Part::Whole},
    {"gl_ModelViewMatrixInverseTranspose", "", "state.matrix.modelview[0].invtrans", Part::Whole},
    {"gl_ProjectionMatrix", "", "state.matrix.projection", Part::Whole},
    {"gl_ProjectionMatrixInverse", "", "state.matrix.projection.inverse", Part::Whole},
    {"gl_ProjectionMatrixTranspose", "", "state.matrix.projection.transpose", Part::Whole},
    {"gl_ProjectionMatrixInverseTranspose", "", "state.matrix.projection.invtrans", Part::Whole},
    {"gl_ModelViewProjectionMatrix", "", "state.matrix.mvp", Part::Whole},
    {"gl_ModelViewProjectionMatrixInverse", "", "state.matrix.mvp.inverse", Part::Whole},
    {"gl_ModelViewProjectionMatrixTranspose", "", "state.matrix.mvp.transpose", Part::Whole},
    {"gl_ModelViewProjectionMatrixInverseTranspose", "", "state.matrix.mvp.invtrans", Part::Whole},
    {"gl_TextureMatrix", "", "state.matrix.texture[{i}]", Part::Whole},
    {"gl_TextureMatrixInverse", "", "state.matrix.texture[{i}].inverse", Part::Whole},
    {"gl_TextureMatrixTranspose", "", "state.matrix.texture[{i}].transpose", Part::Whole},
    {"gl_TextureMatrixInverseTranspose", "", "state.matrix.texture[{i}].invtrans", Part::Whole},
    // Mesa: the transpose of the inverse modelview's upper-left 3x3.
    {"gl_NormalMatrix", "", "state.matrix.modelview[0].invtrans", Part::Mat3},
    {"gl_DepthRange", "near", "state.depth.range", Part::X},
    {"gl_DepthRange", "far", "state.depth.range", Part::Y},
    {"gl_DepthRange", "diff", "state.depth.range", Part::Z},
    {"gl_ClipPlane", "", "state.clip[{i}].plane", Part::Whole},
    {"gl_Point", "size", "state.point.size", Part::X},
    {"gl_Point", "sizeMin", "state.point.size", Part::Y},
    {"gl_Point", "sizeMax", "state.point.size", Part::Z},
    {"gl_Point", "fadeThresholdSize", "state.point.size", Part::W},
    {"gl_Point", "distanceConstantAttenuation", "state.point.attenuation", Part::X},
    {"gl_Point", "distanceLinearAttenuation", "state.point.attenuation", Part::Y},
    {"gl_Point", "distanceQuadraticAttenuation", "state.point.attenuation", Part::Z},
    {"gl_{F}Material", "emission", "state.material.{f}.emission", Part::Whole},
    {"gl_{F}Material", "ambient", "state.material.{f}.ambient", Part::Whole},
    {"gl_{F}Material", "diffuse", "state.material.{f}.diffuse", Part::Whole},
    {"gl_{F}Material", "specular", "state.material.{f}.specular", Part::Whole},
    {"gl_{F}Material", "shininess", "state.material.{f}.shininess", Part::X},
    {"gl_LightSource", "ambient", "state.light[{i}].ambient", Part::Whole},
    {"gl_LightSource", "diffuse", "state.light[{i}].diffuse", Part::Whole},
    {"gl_LightSource", "specular", "state.light[{i}].specular", Part::Whole},
    {"gl_LightSource", "position", "state.light[{i}].position", Part::Whole},
    {"gl_LightSource", "halfVector", "state.light[{i}].half", Part::Whole},
    {"gl_LightSource", "spotDirection", "state.light[{i}].spot.direction", Part::Xyz},
    {"gl_LightSource", "spotCosCutoff", "state.light[{i}].spot.direction", Part::W},
    {"gl_LightSource", "spotExponent", "state.light[{i}].attenuation", Part::W},
    {"gl_LightSource", "constantAttenuation", "state.light[{i}].attenuation", Part::X},
    {"gl_LightSource", "linearAttenuation", "state.light[{i}].attenuation", Part::Y},
    {"gl_LightSource", "quadraticAttenuation", "state.light[{i}].attenuation", Part::Z},
    {"gl_LightModel", "ambient", "state.lightmodel.ambient", Part::Whole},
    {"gl_{F}LightModelProduct", "sceneColor", "state.lightmodel.{f}.scenecolor", Part::Whole},
    {"gl_{F}LightProduct", "ambient", "state.lightprod[{i}].{f}.ambient", Part::Whole},
    {"gl_{F}LightProduct", "diffuse", "state.lightprod[{i}].{f}.diffuse", Part::Whole},
    {"gl_{F}LightProduct", "specular", "state.lightprod[{i}].{f}.specular", Part::Whole},
    {"gl_TextureEnvColor", "", "state.texenv[{i}].color", Part::Whole},
    {"gl_EyePlane{C}", "", "state.texgen[{i}].eye.{c}", Part::Whole},
    {"gl_ObjectPlane{C}", "", "state.texgen[{i}].object.{c}", Part::Whole},
    {"gl_Fog", "color", "state.fog.color", Part::Whole},
    {"gl_Fog", "density", "state.fog.params", Part::X},
    {"gl_Fog", "start", "state.fog.params", Part::Y},
    {"gl_Fog", "end", "state.fog.params", Part::Z},
    {"gl_Fog", "scale", "state.fog.params", Part::W},
};

struct Path {
  std::string base;
  int index = -1;
  std::string member;
};

Path ParsePath(std::string_view path) {
  Path p;
  const size_t bracket = path.find('[');
  const size_t dot = path.find('.');
  p.base = std::string(path.substr(0, std::min(bracket, dot)));
  if (bracket != std::string_view::npos && bracket < dot) {
    p.index = std::atoi(std::string(path.substr(bracket + 1)).c_str());
  }
  if (dot != std::string_view::npos) p.member = std::string(path.substr(dot + 1));
  return p;
}

// The entry's base with {F} and {C} filled so that it reads `base`; the fills in `f`, `c`.
bool MatchBase(std::string_view pattern, std::string_view base, std::string* f, std::string* c) {
  for (std::string_view face : {"Front", "Back"}) {
    for (std::string_view coord : {"S", "T", "R", "Q"}) {
      std::string s(pattern);
      if (const size_t at = s.find("{F}"); at != std::string::npos) s.replace(at, 3, face);
      if (const size_t at = s.find("{C}"); at != std::string::npos) s.replace(at, 3, coord);
      if (s == base) {
        *f = face == "Front" ? "front" : "back";
        *c = std::string(1, static_cast<char>(coord[0] - 'A' + 'a'));
        return true;
      }
    }
  }
  return false;
}

std::string Spell(std::string_view pattern, int index, const std::string& f, const std::string& c) {
  std::string s(pattern);
  for (const auto& [key, value] :
       {std::pair<std::string, std::string>{"{i}", std::to_string(index)},
        {"{f}", f},
        {"{c}", c}}) {
    if (const size_t at = s.find(key); at != std::string::npos) s.replace(at, key.size(), value);
  }
  return s;
}

// glstate's value of `spelling`; an index past glstate's model (clip planes 6 to 7: Mesa has
// 8) reads GL's initial (0, 0, 0, 0).
bool Evaluate(const arbvp::GlState& state, const std::string& spelling, glstate::UniformData* value,
              std::string* error) {
  const arbvp::ProgramParameters none;
  if (glstate::UniformValue(state, none, spelling, value)) return true;
  glstate::StateRef beyond;
  if (glstate::ParseStateSpelling(spelling, &beyond)) {
    *value = glstate::UniformData{};
    return true;
  }
  *error = fmt::format("glstate cannot evaluate '{}'", spelling);
  return false;
}

}  // namespace

bool BuiltinStateValue(std::string_view path, const arbvp::GlState& state,
                       std::vector<float>* value, std::string* error) {
  const Path p = ParsePath(path);
  value->clear();
  if (p.base == "gl_NormalScale") {
    // Mesa: 1 / the length of the third row of the inverse modelview's upper-left 3x3.
    glstate::UniformData inverse;
    if (!Evaluate(state, "state.matrix.modelview[0].inverse", &inverse, error)) return false;
    const float* m = inverse.data.data();
    value->push_back(1.0f / std::sqrt(m[2] * m[2] + m[6] * m[6] + m[10] * m[10]));
    return true;
  }
  if (p.base == "gl_LightSource" && p.member == "spotCutoff") {
    if (p.index < 0 || p.index >= glstate::kMaxLights) {
      *error = fmt::format("no light {}", p.index);
      return false;
    }
    value->push_back(state.light[static_cast<size_t>(p.index)].spot_cutoff);
    return true;
  }
  for (const StateEntry& e : kState) {
    std::string f;
    std::string c;
    if (e.member != p.member || !MatchBase(e.base, p.base, &f, &c)) continue;
    glstate::UniformData data;
    if (!Evaluate(state, Spell(e.spelling, std::max(p.index, 0), f, c), &data, error)) {
      return false;
    }
    const float* d = data.data.data();
    switch (e.part) {
      case Part::Whole:
        value->assign(d, d + (data.type == glstate::UniformType::Matrix ? 16 : 4));
        break;
      case Part::X:
      case Part::Y:
      case Part::Z:
      case Part::W:
        value->push_back(d[static_cast<int>(e.part) - static_cast<int>(Part::X)]);
        break;
      case Part::Xyz:
        value->assign(d, d + 3);
        break;
      case Part::Mat3:
        for (size_t col = 0; col < 3; ++col) {
          value->insert(value->end(), d + 4 * col, d + 4 * col + 3);
        }
        break;
    }
    return true;
  }
  *error = fmt::format("no value for the built-in uniform {}", path);
  return false;
}

}  // namespace arbiter::runtime::glsl_vulkan
