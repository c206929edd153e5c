// --translate to a target without GL's built-in state (glsl330, es300, ...): the runner keeps
// the GL state the commands set in a glstate::GlState, as a port does, and feeds the
// translation's uniforms from it through the binding map and glstate::UniformValue; vertex
// inputs go to the generic attributes the binding map names (docs/run.md, "--translate").
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "arbiter/glstate/uniforms.h"
#include "shader_test/session.h"
#include "shader_test/words.h"

namespace arbiter::runtime::shader_test {
namespace {

// GL's current value of a vertex input before any command sets it (OpenGL 2.0 table 6.5):
// colour (1, 1, 1, 1), normal (0, 0, 1), every other input (0, 0, 0, 1).
std::array<float, 4> InitialAttribute(const std::string& binding) {
  if (binding == "vertex.color" || binding == "vertex.color.primary") return {1, 1, 1, 1};
  if (binding == "vertex.normal") return {0, 0, 1, 1};
  return {0, 0, 0, 1};
}

// GL clamps the fog and texture environment colours to [0, 1] when they are specified.
glstate::Vec4 Clamped(glstate::Vec4 v) {
  for (float& x : v) x = std::clamp(x, 0.0f, 1.0f);
  return v;
}

glstate::Vec4 ToVec4(const glm::vec4& v) { return {v.x, v.y, v.z, v.w}; }

}  // namespace

std::string FixedFunctionBinding(const std::string& column) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 5> kColumns{{
      {"gl_Vertex", "vertex.position"},
      {"gl_Normal", "vertex.normal"},
      {"gl_Color", "vertex.color"},
      {"gl_SecondaryColor", "vertex.color.secondary"},
      {"gl_FogCoord", "vertex.fogcoord"},
  }};
  for (const auto& [name, binding] : kColumns) {
    if (column == name) return std::string(binding);
  }
  int unit = -1;
  if (column.rfind("gl_MultiTexCoord", 0) == 0 && ParseInt(column.substr(16), &unit) && unit >= 0 &&
      unit < 8) {
    return fmt::format("vertex.texcoord[{}]", unit);
  }
  return "";
}

bool Session::EnableIsUniform(GLenum cap) const {
  if (!StateUniforms()) return false;
  const int i = static_cast<int>(cap) - GL_CLIP_PLANE0;
  const std::string spelling = fmt::format("clip[{}].enabled", i);
  return i >= 0 && i < glstate::kMaxClipPlanes &&
         std::any_of(bindings_.state.begin(), bindings_.state.end(),
                     [&](const arbvp::StateUniform& u) { return u.binding == spelling; });
}

int Session::AttributeLocation(const std::string& binding) const {
  const std::string alias = binding == "vertex.color" ? "vertex.color.primary" : binding;
  for (const arbvp::AttributeBinding& a : bindings_.attributes) {
    if (a.binding == binding || a.binding == alias) return a.location;
  }
  return -1;
}

// A vertex program alone: GL's fixed-function fragment stage, for what a vertex program of
// this corpus leaves to it (no texturing, no fog): the interpolated primary colour. The
// version line is the translation's.
std::string Session::StandInFragmentShader(const std::string& vertex) const {
  std::string colour;
  for (const arbvp::RegisterMapping& m : bindings_.outputs) {
    if (m.stage == arbvp::ProgramKind::Vertex &&
        (m.binding == "result.color" || m.binding == "result.color.primary" ||
         m.binding == "result.color.front" || m.binding == "result.color.front.primary")) {
      colour = m.glsl;
    }
  }
  const std::string version = vertex.substr(0, vertex.find('\n'));
  const bool es = version.find(" es") != std::string::npos || version == "#version 100";
  const bool modern =
      version != "#version 100" && version != "#version 110" && version != "#version 120";
  std::string text = version + "\n// GL's fixed-function fragment stage: the primary colour.\n";
  if (es) text += "precision highp float;\n";
  if (!colour.empty()) text += fmt::format("{} vec4 {};\n", modern ? "in" : "varying", colour);
  // The user clip planes of a GLSL ES translation arrive as two varyings to discard by
  // (arbvp's kClipVaryings: the translation declares them when it writes them).
  std::string discard;
  if (vertex.find(" vec4 arb_user_clip0;") != std::string::npos) {
    const char* in = modern ? "in" : "varying";
    text += fmt::format("{0} vec4 arb_user_clip0;\n{0} vec2 arb_user_clip1;\n", in);
    discard =
        "if (any(lessThan(arb_user_clip0, vec4(0.0))) || any(lessThan(arb_user_clip1, "
        "vec2(0.0)))) discard; ";
  }
  if (modern) text += "layout(location = 0) out vec4 arb_fragcolor;\n";
  const std::string value = colour.empty() ? "vec4(0.0, 0.0, 0.0, 1.0)" : colour;
  text += fmt::format("void main() {{ {}{} = {}; }}\n", discard,
                      modern ? "arb_fragcolor" : "gl_FragColor", value);
  return text;
}

// A fragment program alone: GL's fixed-function vertex stage without lighting, texgen or
// fog-coordinate arrays, for the inputs the fragment program reads: position by the MVP
// matrix, the primary and secondary colours clamped, texture coordinate n by texture matrix
// n, the fog coordinate as the eye-space distance |z| (GL_FRAGMENT_DEPTH). Its matrices and
// inputs join the binding map, so that they are fed like the translation's own.
std::string Session::StandInVertexShader(const std::string& fragment) {
  const std::string version = fragment.substr(0, fragment.find('\n'));
  const bool es = version.find(" es") != std::string::npos || version == "#version 100";
  const bool modern = version != "#version 100";
  std::string declarations;
  std::string body;
  auto input = [&](const std::string& name, int location, const std::string& binding) {
    declarations += modern ? fmt::format("layout(location = {}) in vec4 {};\n", location, name)
                           : fmt::format("attribute vec4 {};\n", name);
    bindings_.attributes.push_back({name, location, binding});
  };
  auto matrix = [&](const std::string& name, const std::string& binding) {
    declarations += fmt::format("uniform mat4 {};\n", name);
    bindings_.state.push_back({name, "mat4", binding, -1, ""});
  };
  const char* out = modern ? "out" : "varying";
  input("arb_ff_position", 0, "vertex.position");
  matrix("arb_ff_mvp", "state.matrix.mvp");
  body += "  gl_Position = arb_ff_mvp * arb_ff_position;\n";
  for (const arbvp::RegisterMapping& m : bindings_.inputs) {
    if (m.stage != arbvp::ProgramKind::Fragment) continue;
    int unit = -1;
    if (m.binding == "fragment.color.primary" || m.binding == "fragment.color.secondary") {
      const bool primary = m.binding == "fragment.color.primary";
      const std::string name = primary ? "arb_ff_color0" : "arb_ff_color1";
      input(name, primary ? 3 : 4, primary ? "vertex.color.primary" : "vertex.color.secondary");
      declarations += fmt::format("{} vec4 {};\n", out, m.glsl);
      body += fmt::format("  {} = clamp({}, 0.0, 1.0);\n", m.glsl, name);
    } else if (std::sscanf(m.binding.c_str(), "fragment.texcoord[%d]", &unit) == 1 && unit >= 0 &&
               unit < 8) {
      input(fmt::format("arb_ff_texcoord{}", unit), 8 + unit,
            fmt::format("vertex.texcoord[{}]", unit));
      matrix(fmt::format("arb_ff_texture{}", unit), fmt::format("state.matrix.texture[{}]", unit));
      declarations += fmt::format("{} vec4 {};\n", out, m.glsl);
      body += fmt::format("  {0} = arb_ff_texture{1} * arb_ff_texcoord{1};\n", m.glsl, unit);
    } else if (m.binding == "fragment.fogcoord") {
      matrix("arb_ff_modelview", "state.matrix.modelview[0]");
      declarations += fmt::format("{} float arb_fogcoord;\n", out);
      body += "  arb_fogcoord = abs((arb_ff_modelview * arb_ff_position).z);\n";
    }
  }
  return fmt::format(
      "{}\n// GL's fixed-function vertex stage for the inputs the fragment program reads.\n{}{}"
      "void main() {{\n{}}}\n",
      version, es ? "precision highp float;\n" : "", declarations, body);
}

void Session::UploadStateUniforms() {
  // program.env per target, program.local per program: one ProgramParameters per stage.
  std::array<glstate::ProgramParameters, 2> params;
  for (const auto& [key, value] : parameters_) {
    auto& p = params[key.target == arbvp::ProgramKind::Vertex ? 0 : 1];
    (key.local ? p.local : p.env)[key.index] = value;
  }
  for (const arbvp::ParameterArray& p : bindings_.parameters) {
    const GLint location = gl_.GetUniformLocation(program_, p.name.c_str());
    if (location < 0) continue;
    const glstate::ProgramParameters& stage =
        params[p.target == arbvp::ProgramKind::Vertex ? 0 : 1];
    std::vector<float> values;
    for (int i = 0; i < p.size; ++i) {
      const glstate::Vec4 v = glstate::ParameterValue(p.local ? stage.local : stage.env, i);
      values.insert(values.end(), v.begin(), v.end());
    }
    gl_.Uniform4fv(location, p.size, values.data());
  }
  state_.framebuffer_height = static_cast<float>(window_.height);  // the test's window
  for (const arbvp::StateUniform& s : bindings_.state) {
    const GLint location = gl_.GetUniformLocation(program_, s.name.c_str());
    if (location < 0) continue;
    glstate::UniformData value;
    if (!glstate::UniformValue(state_, params[0], s.binding, &value)) {
      Error(fmt::format("the host library has no value for the translation's uniform {} ({})",
                        s.name, s.binding));
    }
    if (value.type == glstate::UniformType::Matrix) {
      gl_.UniformMatrix4fv(location, 1, GL_FALSE, value.data.data());
    } else {
      gl_.Uniform4fv(location, 1, value.data.data());
    }
  }
  // The current values of the inputs no array feeds (arrays enabled later override them).
  // Attribute 0 is never set: on a compatibility context that would emit a vertex.
  for (const arbvp::AttributeBinding& a : bindings_.attributes) {
    if (a.location <= 0) continue;
    auto it = current_.find(a.binding == "vertex.color.primary" ? "vertex.color" : a.binding);
    const std::array<float, 4> v = it != current_.end() ? it->second : InitialAttribute(a.binding);
    gl_.VertexAttrib4fvARB(static_cast<GLuint>(a.location), v.data());
  }
}

// Keeps state_ as GL keeps its state after the command (words: the command's arguments,
// already checked by the command). Positions, directions and planes are stored in eye space,
// transformed by the modelview matrix current when they are set, as GL stores them.
void Session::TrackState(const std::string& command, const std::vector<std::string>& a) {
  auto values = [&](size_t first) {
    if (first < a.size() && a[first] == "float") ++first;
    std::array<float, 16> v{};
    for (size_t i = first; i < a.size() && i - first < 16; ++i) v[i - first] = Float(a, i);
    return v;
  };
  auto vec4 = [](const std::array<float, 16>& v) { return glstate::Vec4{v[0], v[1], v[2], v[3]}; };
  if (command == "color") {
    current_["vertex.color"] = {Float(a, 0), Float(a, 1), Float(a, 2), Float(a, 3)};
  } else if (command == "texcoord") {
    current_[fmt::format("vertex.texcoord[{}]", Int(a, 0))] = {Float(a, 1), Float(a, 2),
                                                               Float(a, 3), Float(a, 4)};
  } else if (command == "ortho" || command == "frustum") {
    std::array<float, 6> f{0.0f,  static_cast<float>(window_.width),
                           0.0f,  static_cast<float>(window_.height),
                           -1.0f, 1.0f};
    for (size_t i = 0; i < a.size() && i < 6; ++i) f[i] = Float(a, i);
    state_.projection = command == "ortho" ? glm::ortho(f[0], f[1], f[2], f[3], f[4], f[5])
                                           : glm::frustum(f[0], f[1], f[2], f[3], f[4], f[5]);
    state_.modelview = glm::mat4(1.0f);
  } else if (command == "clip plane") {
    const int i = Int(a, 0);
    const glm::vec4 p(Float(a, 1), Float(a, 2), Float(a, 3), Float(a, 4));
    // GL 2.0 section 2.12: the plane is stored as p * inverse(modelview).
    if (i < glstate::kMaxClipPlanes) {
      state_.clip_plane[static_cast<size_t>(i)] = ToVec4(p * glm::inverse(state_.modelview));
    }
  } else if (command == "enable" || command == "disable") {
    // GL_CLIP_PLANEn (GL_CLIP_DISTANCEn in core GL): read as clip[n].enabled.
    const GLenum cap = Enum(a.at(0));
    const int i = static_cast<int>(cap) - GL_CLIP_PLANE0;
    if (i >= 0 && i < glstate::kMaxClipPlanes) {
      state_.clip_enabled[static_cast<size_t>(i)] = command == "enable";
    }
  } else if (command == "depthrange") {
    state_.depth_near = std::clamp(Float(a, 0), 0.0f, 1.0f);
    state_.depth_far = std::clamp(Float(a, 1), 0.0f, 1.0f);
  } else if (command == "light") {
    glstate::LightState& l = state_.light[static_cast<size_t>(Int(a, 0))];
    const GLenum pname = Enum(a[1]);
    const std::array<float, 16> v = values(2);
    switch (pname) {
      case GL_AMBIENT:
        l.ambient = vec4(v);
        break;
      case GL_DIFFUSE:
        l.diffuse = vec4(v);
        break;
      case GL_SPECULAR:
        l.specular = vec4(v);
        break;
      case GL_POSITION:
        l.position = ToVec4(state_.modelview * glm::vec4(v[0], v[1], v[2], v[3]));
        break;
      case GL_SPOT_DIRECTION: {
        const glm::vec3 d = glm::mat3(state_.modelview) * glm::vec3(v[0], v[1], v[2]);
        l.spot_direction = {d.x, d.y, d.z};
        break;
      }
      case GL_SPOT_EXPONENT:
        l.spot_exponent = v[0];
        break;
      case GL_SPOT_CUTOFF:
        l.spot_cutoff = v[0];
        break;
      case GL_CONSTANT_ATTENUATION:
        l.constant_attenuation = v[0];
        break;
      case GL_LINEAR_ATTENUATION:
        l.linear_attenuation = v[0];
        break;
      case GL_QUADRATIC_ATTENUATION:
        l.quadratic_attenuation = v[0];
        break;
      default:
        break;
    }
  } else if (command == "material") {
    const GLenum face = Enum(a[0]);
    const GLenum pname = Enum(a[1]);
    const std::array<float, 16> v = values(2);
    for (size_t f = 0; f < 2; ++f) {
      if (face != GL_FRONT_AND_BACK && face != (f == 0 ? GL_FRONT : GL_BACK)) continue;
      glstate::MaterialState& m = state_.material[f];
      if (pname == GL_AMBIENT || pname == GL_AMBIENT_AND_DIFFUSE) m.ambient = vec4(v);
      if (pname == GL_DIFFUSE || pname == GL_AMBIENT_AND_DIFFUSE) m.diffuse = vec4(v);
      if (pname == GL_SPECULAR) m.specular = vec4(v);
      if (pname == GL_EMISSION) m.emission = vec4(v);
      if (pname == GL_SHININESS) m.shininess = v[0];
    }
  } else if (command == "lightmodel") {
    if (Enum(a[0]) == GL_LIGHT_MODEL_AMBIENT) state_.light_model_ambient = vec4(values(1));
  } else if (command == "fog") {
    const GLenum pname = Enum(a[0]);
    if (a.size() == 2 && a[1].rfind("GL_", 0) == 0) return;  // the mode: no state.fog value
    const std::array<float, 16> v = values(1);
    if (pname == GL_FOG_COLOR) state_.fog_color = Clamped(vec4(v));
    if (pname == GL_FOG_DENSITY) state_.fog_density = v[0];
    if (pname == GL_FOG_START) state_.fog_start = v[0];
    if (pname == GL_FOG_END) state_.fog_end = v[0];
  } else if (command == "texenv") {
    if (Enum(a[1]) == GL_TEXTURE_ENV_COLOR) {
      state_.texenv_color[static_cast<size_t>(Int(a, 0))] = Clamped(vec4(values(2)));
    }
  } else if (command == "matrix") {
    const std::array<float, 16> v = values(1);
    const glm::mat4 m = glm::make_mat4(v.data());
    const GLenum which = Enum(a[0]);
    if (which == GL_MODELVIEW) state_.modelview = m;
    if (which == GL_PROJECTION) state_.projection = m;
    if (which >= GL_TEXTURE0 && which < GL_TEXTURE0 + 8) state_.texture[which - GL_TEXTURE0] = m;
    if (which >= GL_MATRIX0_ARB && which < GL_MATRIX0_ARB + 8) {
      state_.program[which - GL_MATRIX0_ARB] = m;
    }
  }
}

}  // namespace arbiter::runtime::shader_test
