// Programs of the GLSL exec: compiling and linking, active uniforms and their values, and
// the attributes of a vertex. See run.h.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "glsl_exec/run.h"
#include "glsl_exec/types.h"

namespace arbiter::runtime::glsl_exec {
namespace {

std::string Log(const Gl& gl, GLuint object, bool program) {
  GLint length = 0;
  if (program) {
    gl.GetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  } else {
    gl.GetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  }
  std::vector<char> log(static_cast<size_t>(std::max(length, 1)), '\0');
  if (program) {
    gl.GetProgramInfoLog(object, length, nullptr, log.data());
  } else {
    gl.GetShaderInfoLog(object, length, nullptr, log.data());
  }
  std::string text(log.data());
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

GLuint Compile(const Gl& gl, GLenum type, const std::string& text, std::string* error) {
  GLuint shader = gl.CreateShader(type);
  const GLchar* source = text.c_str();
  gl.ShaderSource(shader, 1, &source, nullptr);
  gl.CompileShader(shader);
  GLint ok = GL_FALSE;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok == GL_TRUE) return shader;
  *error = fmt::format("mesa rejected the {} shader: {}",
                       type == GL_VERTEX_SHADER ? "vertex" : "fragment", Log(gl, shader, false));
  gl.DeleteShader(shader);
  return 0;
}

int Columns(const GlslInputSlot& slot) { return LookUpType(slot.type).columns; }

}  // namespace

bool LoadExtraGl(const exec::GetProcFn& get_proc, Gl* gl, std::string* error) {
#define ARBITER_GLSL_EXEC_GL_LOAD(type, member, name)                   \
  if (exec::GlProc proc = get_proc(name); proc != nullptr) {            \
    gl->member = reinterpret_cast<type>(proc);                          \
  } else {                                                              \
    *error = fmt::format("the GL context does not provide '{}'", name); \
    return false;                                                       \
  }
  ARBITER_GLSL_EXEC_GL_FUNCTIONS(ARBITER_GLSL_EXEC_GL_LOAD)
#undef ARBITER_GLSL_EXEC_GL_LOAD
  return true;
}

int AttributeLocation(const std::vector<GlslInputSlot>& attributes, const std::string& name) {
  int location = 1;  // 0 is gl_Vertex's
  for (const GlslInputSlot& slot : attributes) {
    if (slot.name.starts_with("gl_")) continue;
    if (slot.name == name) return location;
    location += Columns(slot);
  }
  return -1;
}

GLuint BuildProgram(const Gl& gl, const ProgramSpec& spec, std::string* error) {
  std::vector<GLuint> shaders;
  bool ok = true;
  for (const std::string& text : spec.vertex) {
    if (!ok) break;
    shaders.push_back(Compile(gl, GL_VERTEX_SHADER, text, error));
    ok = shaders.back() != 0;
  }
  for (const std::string& text : spec.fragment) {
    if (!ok) break;
    shaders.push_back(Compile(gl, GL_FRAGMENT_SHADER, text, error));
    ok = shaders.back() != 0;
  }
  if (!ok) {
    for (GLuint s : shaders) gl.DeleteShader(s);
    return 0;
  }
  GLuint program = gl.CreateProgram();
  for (GLuint s : shaders) gl.AttachShader(program, s);
  for (const GlslInputSlot& slot : spec.attributes) {
    const int location = AttributeLocation(spec.attributes, slot.name);
    if (location >= 0) {
      gl.BindAttribLocation(program, static_cast<GLuint>(location), slot.name.c_str());
    }
  }
  if (!spec.capture.empty()) {
    std::vector<const GLchar*> names;
    for (const std::string& name : spec.capture) names.push_back(name.c_str());
    gl.TransformFeedbackVaryings(program, static_cast<GLsizei>(names.size()), names.data(),
                                 GL_INTERLEAVED_ATTRIBS);
  }
  gl.LinkProgram(program);
  for (GLuint s : shaders) gl.DeleteShader(s);  // the program keeps them while attached
  GLint linked = GL_FALSE;
  gl.GetProgramiv(program, GL_LINK_STATUS, &linked);
  if (linked == GL_TRUE) return program;
  *error = fmt::format("mesa cannot link the program: {}", Log(gl, program, true));
  gl.DeleteProgram(program);
  return 0;
}

std::vector<ActiveUniform> ActiveUniforms(const Gl& gl, GLuint program) {
  std::vector<ActiveUniform> out;
  GLint count = 0;
  gl.GetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
  GLint max_length = 0;
  gl.GetProgramiv(program, GL_ACTIVE_UNIFORM_MAX_LENGTH, &max_length);
  std::vector<GLchar> name(static_cast<size_t>(std::max(max_length, 1)) + 1, '\0');
  for (GLint i = 0; i < count; ++i) {
    ActiveUniform u;
    GLsizei length = 0;
    gl.GetActiveUniform(program, static_cast<GLuint>(i), static_cast<GLsizei>(name.size()), &length,
                        &u.size, &u.type, name.data());
    u.name.assign(name.data(), static_cast<size_t>(length));
    if (u.name.starts_with("gl_") || u.name.starts_with("arbiter_")) continue;
    out.push_back(std::move(u));
  }
  return out;
}

namespace {

void Upload(const Gl& gl, GLint location, const TypeInfo& type, GLsizei count,
            const std::vector<float>& values) {
  if (type.base == BaseKind::Int || type.base == BaseKind::Sampler || type.base == BaseKind::Bool) {
    std::vector<GLint> ints;
    ints.reserve(values.size());
    for (float v : values) ints.push_back(static_cast<GLint>(v));
    switch (type.components) {
      case 1:
        gl.Uniform1iv(location, count, ints.data());
        return;
      case 2:
        gl.Uniform2iv(location, count, ints.data());
        return;
      case 3:
        gl.Uniform3iv(location, count, ints.data());
        return;
      default:
        gl.Uniform4iv(location, count, ints.data());
        return;
    }
  }
  const float* data = values.data();
  switch (type.gl_type) {
    case GL_FLOAT:
      gl.Uniform1fv(location, count, data);
      return;
    case GL_FLOAT_VEC2:
      gl.Uniform2fv(location, count, data);
      return;
    case GL_FLOAT_VEC3:
      gl.Uniform3fv(location, count, data);
      return;
    case GL_FLOAT_VEC4:
      gl.Uniform4fv(location, count, data);
      return;
    case GL_FLOAT_MAT2:
      gl.UniformMatrix2fv(location, count, GL_FALSE, data);
      return;
    case GL_FLOAT_MAT3:
      gl.UniformMatrix3fv(location, count, GL_FALSE, data);
      return;
    case GL_FLOAT_MAT4:
      gl.UniformMatrix4fv(location, count, GL_FALSE, data);
      return;
    case GL_FLOAT_MAT2x3:
      gl.UniformMatrix2x3fv(location, count, GL_FALSE, data);
      return;
    case GL_FLOAT_MAT2x4:
      gl.UniformMatrix2x4fv(location, count, GL_FALSE, data);
      return;
    case GL_FLOAT_MAT3x2:
      gl.UniformMatrix3x2fv(location, count, GL_FALSE, data);
      return;
    case GL_FLOAT_MAT3x4:
      gl.UniformMatrix3x4fv(location, count, GL_FALSE, data);
      return;
    case GL_FLOAT_MAT4x2:
      gl.UniformMatrix4x2fv(location, count, GL_FALSE, data);
      return;
    case GL_FLOAT_MAT4x3:
      gl.UniformMatrix4x3fv(location, count, GL_FALSE, data);
      return;
    default:
      return;
  }
}

}  // namespace

void UploadUniform(const Gl& gl, GLint location, std::string_view type, GLsizei count,
                   const std::vector<float>& values) {
  Upload(gl, location, LookUpType(type), count, values);
}

GLuint PrepareProgram(const RunContext& run, const ProgramSpec& spec, std::string* error) {
  const GLuint program = BuildProgram(run.gl, spec, error);
  if (program == 0) return 0;
  run.gl.UseProgram(program);
  for (ActiveUniform& u : ActiveUniforms(run.gl, program)) {
    const bool seen = std::any_of(run.active->begin(), run.active->end(),
                                  [&](const ActiveUniform& a) { return a.name == u.name; });
    if (!seen) run.active->push_back(std::move(u));
  }
  if (!SetUniforms(run.gl, program, run.inputs, run.used_uniforms, run.applied, run.usage)) {
    run.gl.UseProgram(0);
    run.gl.DeleteProgram(program);
    return 0;
  }
  return program;
}

bool MatchUniform(const std::string& active, int size, const std::string& name, int* first,
                  bool* whole) {
  *first = 0;
  *whole = false;
  if (active == name) return true;
  if (!active.ends_with("[0]")) return false;
  const std::string base = active.substr(0, active.size() - 3);
  if (name == base) {
    *whole = true;
    return true;
  }
  if (!name.starts_with(base + "[") || !name.ends_with("]")) return false;
  const std::string index = name.substr(base.size() + 1, name.size() - base.size() - 2);
  if (index.empty() || !std::all_of(index.begin(), index.end(), ::isdigit)) return false;
  *first = std::stoi(index);
  return *first < size;
}

bool CheckUniformValues(const std::string& name, const TypeInfo& type, int size, bool whole,
                        const std::vector<float>& values, size_t* elements, std::string* usage) {
  const size_t per = static_cast<size_t>(type.components);
  *elements = values.size() / per;
  const bool count_ok = values.size() % per == 0 && *elements >= 1 &&
                        (whole ? *elements <= static_cast<size_t>(size) : *elements == 1);
  if (!count_ok) {
    *usage = whole ? fmt::format(
                         "--uniform {}: {} is a {}[{}] and takes {} value(s) per element, "
                         "for 1 to {} elements, not {} value(s)",
                         name, name, type.name, size, per, size, values.size())
                   : fmt::format("--uniform {}: {} is a {} and takes {} value(s), not {}", name,
                                 name, type.name, per, values.size());
    return false;
  }
  if (type.base != BaseKind::Float) {
    for (float v : values) {
      if (v != std::trunc(v) || !std::isfinite(v)) {
        *usage = fmt::format("--uniform {}: {} is of type {}: its values are integers", name, name,
                             type.name);
        return false;
      }
    }
  }
  return true;
}

bool SetUniforms(const Gl& gl, GLuint program, const GlslExecInputs& inputs,
                 std::set<std::string>* used, std::set<size_t>* applied, std::string* usage) {
  const std::vector<ActiveUniform> active = ActiveUniforms(gl, program);
  for (size_t a = 0; a < inputs.uniforms.size(); ++a) {
    const auto& [name, values] = inputs.uniforms[a];
    for (const ActiveUniform& u : active) {
      int first = 0;
      bool whole = false;
      if (!MatchUniform(u.name, u.size, name, &first, &whole)) continue;
      const TypeInfo type = LookUpGlType(u.type);
      if (type.components == 0) {
        *usage = fmt::format("--uniform {}: the uniform's type (0x{:04x}) is not supported", name,
                             u.type);
        return false;
      }
      size_t elements = 0;
      if (!CheckUniformValues(name, type, u.size, whole, values, &elements, usage)) return false;
      const GLint location = gl.GetUniformLocation(program, name.c_str());
      if (location >= 0) {
        Upload(gl, location, type, static_cast<GLsizei>(elements), values);
      }
      used->insert(u.name);
      applied->insert(a);
    }
  }
  return true;
}

void EmitVertex(const Gl& gl, const std::vector<GlslInputSlot>& attributes,
                const std::map<std::string, std::vector<float>>& v) {
  auto value = [&](const std::string& name) -> std::vector<float> {
    auto it = v.find(name);
    if (it != v.end()) return it->second;
    return {0.0f, 0.0f, 0.0f, 1.0f};
  };
  gl.Normal3fv(value("gl_Normal").data());
  gl.Color4fv(value("gl_Color").data());
  gl.SecondaryColor3fv(value("gl_SecondaryColor").data());
  gl.FogCoordf(value("gl_FogCoord")[0]);
  for (int k = 0; k < arbvp::kMaxTextureCoords; ++k) {
    gl.MultiTexCoord4fv(static_cast<GLenum>(GL_TEXTURE0 + k),
                        value(fmt::format("gl_MultiTexCoord{}", k)).data());
  }
  for (const GlslInputSlot& slot : attributes) {
    if (slot.name.starts_with("gl_")) continue;
    const int location = AttributeLocation(attributes, slot.name);
    const std::vector<float> numbers = value(slot.name);
    const int columns = Columns(slot);
    const size_t rows = static_cast<size_t>(slot.components / columns);
    for (int c = 0; c < columns; ++c) {
      arbvp::Vec4 column{0.0f, 0.0f, 0.0f, 1.0f};
      for (size_t r = 0; r < rows && static_cast<size_t>(c) * rows + r < numbers.size(); ++r) {
        column[r] = numbers[static_cast<size_t>(c) * rows + r];
      }
      gl.VertexAttrib4fv(static_cast<GLuint>(location + c), column.data());
    }
  }
  gl.Vertex4fv(value("gl_Vertex").data());
}

}  // namespace arbiter::runtime::glsl_exec
