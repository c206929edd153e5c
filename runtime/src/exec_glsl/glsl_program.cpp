// Program objects of the mesa-glsl engine: see glsl_program.h.
#include "exec_glsl/glsl_program.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "arbiter/glstate/uniforms.h"
#include "exec/textures.h"

namespace arbiter::runtime::exec {
namespace {

std::string TrimmedLog(std::vector<char> log) {
  std::string text(log.data());
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

GLuint Compile(const ExecGl& gl, GLenum type, const std::string& text, std::string* error) {
  GLuint shader = gl.CreateShader(type);
  const GLchar* source = text.c_str();
  gl.ShaderSource(shader, 1, &source, nullptr);
  gl.CompileShader(shader);
  GLint ok = GL_FALSE;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok == GL_TRUE) return shader;
  GLint length = 0;
  gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<size_t>(std::max(length, 1)), '\0');
  gl.GetShaderInfoLog(shader, length, nullptr, log.data());
  *error = fmt::format("mesa rejected the adapted GLSL {} shader: {}",
                       type == GL_VERTEX_SHADER ? "vertex" : "fragment", TrimmedLog(log));
  gl.DeleteShader(shader);
  return 0;
}

// The (binding, stage) pairs of every state binding the programs read.
struct StateRef {
  arbvp::Binding binding;
  arbvp::ProgramKind kind;
};
std::vector<StateRef> StateBindings(const ArbPrograms& programs) {
  std::vector<StateRef> out;
  for (const arbvp::Program* p : {programs.vertex, programs.fragment}) {
    if (p == nullptr) continue;
    for (const arbvp::Variable& var : p->vars) {
      for (const arbvp::Binding& b : var.bindings) {
        if (b.kind == arbvp::BindingKind::State) out.push_back({b, p->kind});
      }
    }
  }
  return out;
}

// The matrix a mat4 state uniform stands for, column-major: the emitter names it after the
// matrix with the modifier reduced to none or .inverse (emit_bindings.cpp, MatrixRow), and
// the uniform holds that matrix as GL stores it, so its rows are the ARB rows.
bool MatrixValue(const std::vector<StateRef>& refs, const arbvp::StateUniform& u,
                 const arbvp::GlState& state, std::array<float, 16>* data) {
  for (const StateRef& ref : refs) {
    if (ref.binding.state != arbvp::StateItem::MatrixRow) continue;
    arbvp::Binding whole = ref.binding;
    const bool inverse = whole.modifier == arbvp::MatrixModifier::Inverse ||
                         whole.modifier == arbvp::MatrixModifier::InvTrans;
    whole.modifier = inverse ? arbvp::MatrixModifier::Inverse : arbvp::MatrixModifier::None;
    std::string spelled = arbvp::BindingName(whole, ref.kind);
    spelled = spelled.substr(0, spelled.rfind(".row["));
    if (spelled != u.binding) continue;
    for (int r = 0; r < 4; ++r) {
      whole.row = static_cast<uint8_t>(r);
      const arbvp::Vec4 row = arbvp::ReadStateBinding(state, whole);
      for (size_t c = 0; c < 4; ++c) (*data)[c * 4 + static_cast<size_t>(r)] = row[c];
    }
    return true;
  }
  return false;
}

bool VectorValue(const std::vector<StateRef>& refs, const arbvp::StateUniform& u,
                 const arbvp::GlState& state, arbvp::Vec4* value) {
  for (const StateRef& ref : refs) {
    if (arbvp::BindingName(ref.binding, ref.kind) != u.binding) continue;
    *value = arbvp::ReadStateBinding(state, ref.binding);
    return true;
  }
  return false;
}

void SetSamplers(const ExecGl& gl, GLuint program, const arbvp::BindingMap& map) {
  for (const arbvp::SamplerBinding& s : map.samplers) {
    const GLint location = gl.GetUniformLocation(program, s.name.c_str());
    if (location >= 0) gl.Uniform1i(location, s.unit);
  }
}

}  // namespace

GLuint LinkGlslPass(const ExecGl& gl, const GlslPass& pass, const arbvp::BindingMap& map,
                    const RunPlan& plan, std::string* error) {
  GLuint vs = Compile(gl, GL_VERTEX_SHADER, pass.vertex, error);
  if (vs == 0) return 0;
  GLuint fs = Compile(gl, GL_FRAGMENT_SHADER, pass.fragment, error);
  if (fs == 0) {
    gl.DeleteShader(vs);
    return 0;
  }
  GLuint program = gl.CreateProgram();
  gl.AttachShader(program, vs);
  gl.AttachShader(program, fs);
  if (plan.mode == RunMode::Fragment) {
    for (const GeneratedAttribute& a : FragmentInputAttributes()) {
      gl.BindAttribLocation(program, static_cast<GLuint>(a.location), a.name);
    }
  } else {
    for (const arbvp::AttributeBinding& a : map.attributes) {
      if (a.location >= 0) {
        gl.BindAttribLocation(program, static_cast<GLuint>(a.location), a.name.c_str());
      }
    }
    if (plan.position_attrib >= 0) {
      gl.BindAttribLocation(program, static_cast<GLuint>(plan.position_attrib), kPixelAttribute);
    }
  }
  gl.LinkProgram(program);
  // The program keeps the shaders alive while they are attached.
  gl.DeleteShader(vs);
  gl.DeleteShader(fs);
  GLint ok = GL_FALSE;
  gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok == GL_TRUE) return program;
  GLint length = 0;
  gl.GetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<size_t>(std::max(length, 1)), '\0');
  gl.GetProgramInfoLog(program, length, nullptr, log.data());
  *error = fmt::format("mesa cannot link the adapted GLSL program: {}", TrimmedLog(log));
  gl.DeleteProgram(program);
  return 0;
}

bool SetGlslUniforms(const ExecGl& gl, GLuint program, const arbvp::BindingMap& map,
                     const ArbPrograms& programs, const arbvp::ExecInputs& inputs,
                     std::string* error) {
  for (const arbvp::ParameterArray& p : map.parameters) {
    const GLint location = gl.GetUniformLocation(program, p.name.c_str());
    if (location < 0) continue;  // optimised away
    const arbvp::ProgramParameters& params =
        p.target == arbvp::ProgramKind::Vertex ? inputs.vertex_params : inputs.fragment_params;
    const std::map<int, arbvp::Vec4>& values = p.local ? params.local : params.env;
    std::vector<float> data(static_cast<size_t>(p.size) * 4, 0.0f);
    for (const auto& [index, value] : values) {
      if (index < 0 || index >= p.size) continue;
      std::copy(value.begin(), value.end(), data.begin() + static_cast<ptrdiff_t>(index) * 4);
    }
    gl.Uniform4fv(location, p.size, data.data());
  }
  SetSamplers(gl, program, map);
  const std::vector<StateRef> refs = StateBindings(programs);
  for (const arbvp::StateUniform& u : map.state) {
    const GLint location = gl.GetUniformLocation(program, u.name.c_str());
    if (location < 0) continue;
    bool found = false;
    if (u.type == "mat4") {
      std::array<float, 16> data{};
      found = MatrixValue(refs, u, inputs.state, &data);
      if (found) gl.UniformMatrix4fv(location, 1, GL_FALSE, data.data());
    } else {
      arbvp::Vec4 value{};
      found = VectorValue(refs, u, inputs.state, &value);
      if (found) gl.Uniform4fv(location, 1, value.data());
    }
    if (!found) {
      *error = fmt::format("no binding of the programs is '{}' (uniform {})", u.binding, u.name);
      return false;
    }
  }
  return true;
}

bool SetTargetUniforms(const ExecGl& gl, GLuint program, const arbvp::BindingMap& map,
                       const arbvp::ExecInputs& inputs, int framebuffer_height,
                       std::string* error) {
  glstate::GlState state = inputs.state;
  state.framebuffer_height = static_cast<float>(framebuffer_height);
  for (const auto& [unit, texture] : inputs.textures) {  // read by shadow lookups
    if (unit >= 0 && unit < glstate::kMaxTextureImageUnits) {
      state.depth_texture_mode[static_cast<size_t>(unit)] =
          static_cast<uint32_t>(DepthTextureMode(texture.depth_mode));
    }
  }
  for (const arbvp::ParameterArray& p : map.parameters) {
    const GLint location = gl.GetUniformLocation(program, p.name.c_str());
    if (location < 0) continue;  // optimised away
    const arbvp::ProgramParameters& params =
        p.target == arbvp::ProgramKind::Vertex ? inputs.vertex_params : inputs.fragment_params;
    std::vector<float> data(static_cast<size_t>(p.size) * 4, 0.0f);
    for (int i = 0; i < p.size; ++i) {
      const std::string spelling = fmt::format("program.{}[{}]", p.local ? "local" : "env", i);
      glstate::UniformData value;
      if (!glstate::UniformValue(state, params, spelling, &value)) {
        *error = fmt::format("glstate::UniformValue cannot evaluate '{}' ({})", spelling, p.name);
        return false;
      }
      std::copy_n(value.data.begin(), 4, data.begin() + static_cast<ptrdiff_t>(i) * 4);
    }
    gl.Uniform4fv(location, p.size, data.data());
  }
  SetSamplers(gl, program, map);
  for (const arbvp::StateUniform& u : map.state) {
    const GLint location = gl.GetUniformLocation(program, u.name.c_str());
    if (location < 0) continue;
    glstate::UniformData value;
    if (!glstate::UniformValue(state, inputs.vertex_params, u.binding, &value)) {
      glstate::StateRef beyond;
      if (!glstate::ParseStateSpelling(u.binding, &beyond)) {
        *error = fmt::format("glstate::UniformValue cannot evaluate '{}' ({})", u.binding, u.name);
        return false;
      }
      // A light or clip plane past the model's arrays (gl_state.h): GL's initial value
      // (0, 0, 0, 0), which the interpreter and the ARB engine read too.
      value = glstate::UniformData{};
    }
    const bool matrix = value.type == glstate::UniformType::Matrix;
    if (matrix != (u.type == "mat4")) {
      *error = fmt::format("glstate gives a {} for '{}', the uniform {} is a {}",
                           matrix ? "mat4" : "vec4", u.binding, u.name, u.type);
      return false;
    }
    if (matrix) {
      gl.UniformMatrix4fv(location, 1, GL_FALSE, value.data.data());
    } else {
      gl.Uniform4fv(location, 1, value.data.data());
    }
  }
  return true;
}

}  // namespace arbiter::runtime::exec
