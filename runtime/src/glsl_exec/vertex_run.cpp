// The vertex stage of the GLSL exec: every output the vertex shader writes, captured with
// transform feedback (GL 3.0 2.15; exact, before colour clamping and clipping), one point per
// vector, with rasterisation off. Outputs past the interleaved component limit are captured
// by further runs of the same shader.
#include <fmt/format.h>

#include <algorithm>

#include "exec/framebuffer.h"
#include "glsl_exec/run.h"
#include "glsl_exec/types.h"

namespace arbiter::runtime::glsl_exec {
namespace {

// The built-in outputs of a vertex shader, in the order they are reported.
constexpr std::string_view kBuiltinOutputs[] = {
    "gl_Position",           "gl_PointSize", "gl_ClipVertex",
    "gl_FrontColor",         "gl_BackColor", "gl_FrontSecondaryColor",
    "gl_BackSecondaryColor", "gl_TexCoord",  "gl_FogFragCoord"};

std::string BaseName(const std::string& access) {
  return access.substr(0, std::min(access.find('['), access.find('.')));
}

}  // namespace

std::vector<VertexOutput> VertexOutputs(const glsl::Reflection& vertex) {
  std::vector<VertexOutput> out;
  auto add = [&](std::string name, std::string type, int components) {
    for (const VertexOutput& o : out) {
      if (o.name == name) return;
    }
    out.push_back({std::move(name), std::move(type), components});
  };
  for (std::string_view builtin : kBuiltinOutputs) {
    std::vector<int> texcoords;
    for (const glsl::BuiltinUse& use : vertex.builtins_written) {
      if (BaseName(use.name) != builtin) continue;
      if (builtin != "gl_TexCoord") {
        const bool scalar = builtin == "gl_PointSize" || builtin == "gl_FogFragCoord";
        add(std::string(builtin), scalar ? "float" : "vec4", scalar ? 1 : 4);
      } else if (use.name.size() > builtin.size() && use.name[builtin.size()] == '[') {
        texcoords.push_back(std::stoi(use.name.substr(builtin.size() + 1)));
      } else {  // indexed by a variable: every element of its size
        for (int i = 0; i < std::max(use.components / 4, 1); ++i) texcoords.push_back(i);
      }
    }
    std::sort(texcoords.begin(), texcoords.end());
    for (int i : texcoords) add(fmt::format("gl_TexCoord[{}]", i), "vec4", 4);
  }
  for (const glsl::ReflectedVariable& v : vertex.varyings) {
    if (!v.written) continue;
    const TypeInfo type = LookUpType(v.type);
    if (type.components == 0) continue;
    if (v.array_size == 0) {
      add(v.name, v.type, type.components);
    } else {
      for (int i = 0; i < v.array_size; ++i) {
        add(fmt::format("{}[{}]", v.name, i), v.type, type.components);
      }
    }
  }
  return out;
}

bool RunVertex(const RunContext& run, std::vector<GlslVectorResult>* results, std::string* error) {
  const Gl& gl = run.gl;
  const std::vector<VertexOutput> outputs = VertexOutputs(*run.shaders.vertex_reflection);
  GLint limit = 64;
  gl.GetIntegerv(GL_MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS, &limit);
  // Greedy groups of outputs within the limit; a run with no outputs still sets uniforms.
  std::vector<std::vector<VertexOutput>> groups(1);
  int used = 0;
  for (const VertexOutput& o : outputs) {
    if (used + o.components > limit && !groups.back().empty()) {
      groups.emplace_back();
      used = 0;
    }
    groups.back().push_back(o);
    used += o.components;
  }
  const size_t count = run.inputs.vectors.size();
  gl.ClampColorARB(GL_CLAMP_VERTEX_COLOR_ARB, GL_FALSE);
  // Nothing is rasterised, but a draw needs a complete framebuffer (EGL surfaceless has none).
  exec::Framebuffer framebuffer(gl);
  if (!framebuffer.Create(1, 1, 1, error)) return false;
  for (const std::vector<VertexOutput>& group : groups) {
    ProgramSpec spec;
    spec.vertex = {run.shaders.vertex};
    spec.attributes = run.inputs.slots;
    for (const VertexOutput& o : group) spec.capture.push_back(o.name);
    const GLuint program = PrepareProgram(run, spec, error);
    if (program == 0) return false;
    if (group.empty()) {
      gl.UseProgram(0);
      gl.DeleteProgram(program);
      break;
    }
    // What GL captures per vertex: each varying's type and size as the program has it.
    std::vector<int> components;
    size_t stride = 0;
    for (size_t i = 0; i < group.size(); ++i) {
      GLsizei size = 0;
      GLenum type = 0;
      GLchar name[256];
      gl.GetTransformFeedbackVarying(program, static_cast<GLuint>(i), sizeof name, nullptr, &size,
                                     &type, name);
      components.push_back(LookUpGlType(type).components * size);
      stride += static_cast<size_t>(components.back());
    }
    GLuint buffer = 0;
    gl.GenBuffers(1, &buffer);
    gl.BindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffer);
    std::vector<float> data(std::max<size_t>(count * stride, 1), 0.0f);
    gl.BufferData(GL_TRANSFORM_FEEDBACK_BUFFER,
                  static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
                  GL_STATIC_READ);
    gl.BindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffer);
    gl.Enable(GL_RASTERIZER_DISCARD);
    gl.BeginTransformFeedback(GL_POINTS);
    for (const auto& v : run.inputs.vectors) {
      gl.Begin(GL_POINTS);
      EmitVertex(gl, run.inputs.slots, v);
      gl.End();
    }
    gl.EndTransformFeedback();
    gl.Disable(GL_RASTERIZER_DISCARD);
    gl.GetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0,
                        static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data());
    gl.BindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    gl.BindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, 0);
    gl.DeleteBuffers(1, &buffer);
    gl.UseProgram(0);
    gl.DeleteProgram(program);
    if (const GLenum code = gl.GetError(); code != GL_NO_ERROR) {
      *error = fmt::format("capturing the vertex outputs raised {}", exec::GlErrorName(code));
      return false;
    }
    for (size_t v = 0; v < count; ++v) {
      size_t offset = v * stride;
      for (size_t i = 0; i < group.size(); ++i) {
        GlslOutput out{group[i].name, "vertex", group[i].type, {}};
        const auto n = static_cast<size_t>(components[i]);
        out.value.assign(data.begin() + static_cast<ptrdiff_t>(offset),
                         data.begin() + static_cast<ptrdiff_t>(offset + n));
        offset += n;
        (*results)[v].outputs.push_back(std::move(out));
      }
    }
  }
  return true;
}

}  // namespace arbiter::runtime::glsl_exec
