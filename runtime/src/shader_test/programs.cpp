// The test's programs: ARB programs through glProgramStringARB, GLSL shaders compiled and
// linked as piglit does (piglit_vertex at attribute 0, piglit_texcoord at 1), and under
// --translate the ARB programs replaced by arbiter's GLSL translation with its binding map.
#include <fmt/format.h>

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include "arbiter/glsl/check.h"
#include "arbiter/runtime/translate.h"
#include "shader_test/session.h"
#include "shader_test/words.h"

namespace arbiter::runtime::shader_test {
namespace {

constexpr const char* kPassthrough =
    "#version 110\n"
    "attribute vec4 piglit_vertex;\n"
    "void main() { gl_Position = piglit_vertex; }\n";

const char* StageName(arbvp::ProgramKind kind) {
  return kind == arbvp::ProgramKind::Vertex ? "vertex program" : "fragment program";
}

bool ExpectsLinkError(const ShaderTest& test) {
  for (const ShaderTestLine& c : test.commands) {
    if (c.text.rfind("link error", 0) == 0) return true;
  }
  return false;
}

// Mesa's info log, one entry per non-empty line.
void AddLog(const std::string& prefix, const std::string& log, std::vector<std::string>* out) {
  size_t pos = 0;
  while (pos < log.size()) {
    size_t end = log.find('\n', pos);
    if (end == std::string::npos) end = log.size();
    std::string line = log.substr(pos, end - pos);
    if (!line.empty()) out->push_back(prefix + line);
    pos = end + 1;
  }
}

}  // namespace

bool Session::CheckArb(arbvp::ProgramKind kind, const ShaderTestSource& source,
                       std::unique_ptr<compiler::SourceFile>* file, arbvp::CheckResult* checked) {
  *file = std::make_unique<compiler::SourceFile>(test_.path, source.text);
  compiler::DiagnosticSink sink(20);
  arbvp::CheckOptions options;
  options.expected_kind = kind;
  *checked = arbvp::CheckProgram(**file, options, &sink);
  for (const compiler::Diagnostic& d : sink.diagnostics()) {
    if (d.severity != compiler::Severity::Error) continue;
    compiler::LineCol at = (*file)->Locate(d.range.begin);
    result_.diagnostics.push_back(fmt::format("{}:{}:{}: error: {} [{}]", test_.path,
                                              static_cast<int>(at.line) + source.line, at.column,
                                              d.message, d.info != nullptr ? d.info->code : "arb"));
  }
  return checked->ok && checked->program != nullptr;
}

bool Session::LoadArb(arbvp::ProgramKind kind, const ShaderTestSource& source) {
  const bool vertex = kind == arbvp::ProgramKind::Vertex;
  const GLenum target = vertex ? GL_VERTEX_PROGRAM_ARB : GL_FRAGMENT_PROGRAM_ARB;
  GLuint& id = arb_programs_[vertex ? 0 : 1];
  gl_.GenProgramsARB(1, &id);
  gl_.BindProgramARB(target, id);
  for (int i = 0; i < 16 && gl_.GetError() != GL_NO_ERROR; ++i) {
  }
  gl_.ProgramStringARB(target, GL_PROGRAM_FORMAT_ASCII_ARB,
                       static_cast<GLsizei>(source.text.size()), source.text.data());
  GLint position = -1;
  gl_.GetIntegerv(GL_PROGRAM_ERROR_POSITION_ARB, &position);
  if (gl_.GetError() != GL_NO_ERROR || position != -1) {
    const GLubyte* message = gl_.GetString(GL_PROGRAM_ERROR_STRING_ARB);
    line_ = source.line;
    result_.status = TestStatus::Fail;
    result_.message =
        fmt::format("{}:{}: Mesa rejects the {}: {}", test_.path, source.line, StageName(kind),
                    message != nullptr ? reinterpret_cast<const char*>(message) : "");
    std::unique_ptr<compiler::SourceFile> file;
    arbvp::CheckResult checked;
    CheckArb(kind, source, &file, &checked);
    return false;
  }
  gl_.Enable(target);
  return true;
}

bool Session::TranslateArb(std::string* vertex, std::string* fragment) {
  std::unique_ptr<compiler::SourceFile> files[2];
  arbvp::CheckResult checked[2];
  const ShaderTestSource* sources[2] = {&test_.vertex_program, &test_.fragment_program};
  for (int i = 0; i < 2; ++i) {
    if (sources[i]->line == 0) continue;
    const auto kind = i == 0 ? arbvp::ProgramKind::Vertex : arbvp::ProgramKind::Fragment;
    if (!CheckArb(kind, *sources[i], &files[i], &checked[i])) {
      result_.status = TestStatus::Fail;
      result_.message = fmt::format("{}:{}: arbiter rejects the {}, so it cannot be translated",
                                    test_.path, sources[i]->line, StageName(kind));
      return false;
    }
  }
  // glslang's self-check reads GLSL 1.10 and 1.20; the other dialects are checked by Mesa's
  // compiler when the program is built (a rejection fails the test with Mesa's log).
  const bool self_check = options_.emit.target == arbvp::EmitTarget::Glsl110 ||
                          options_.emit.target == arbvp::EmitTarget::Glsl120;
  CheckedTranslation t = self_check
                             ? TranslateChecked(checked[0].program.get(), checked[1].program.get(),
                                                options_.emit, files[0].get(), files[1].get())
                             : EmitTranslation(checked[0].program.get(), checked[1].program.get(),
                                               options_.emit, files[0].get(), files[1].get());
  if (!self_check && !t.refused && t.error.empty()) t.ok = true;
  if (!t.ok && t.refused) {
    // A construct the target cannot express: the test cannot run there, which is no failure.
    result_.status = TestStatus::Skip;
    result_.message = fmt::format("{}: the translation to {} refuses the program: {}", test_.path,
                                  arbvp::EmitTargetTitle(options_.emit.target), t.error);
    return false;
  }
  if (!t.ok) {
    result_.status = TestStatus::Fail;
    result_.message =
        fmt::format("{}: the translation to GLSL failed its self-check: {}", test_.path, t.error);
    return false;
  }
  *vertex = std::move(t.vertex);
  *fragment = std::move(t.fragment);
  bindings_ = std::move(t.bindings);
  translated_ = true;
  return true;
}

std::string Session::VersionDirective() const { return ShaderTestVersionDirective(test_); }

std::string Session::WithVersion(const std::string& text) const {
  if (text.find("#version") != std::string::npos) return text;
  return VersionDirective() + text;
}

void Session::AddGlslDiagnostics(const std::string& stage, const std::string& text, int line) {
  // The shader text padded so that glslang's line numbers are the test file's; a #version
  // shader_runner adds goes on the section's header line.
  std::string versioned = WithVersion(text);
  const size_t added = versioned.size() - text.size();
  const auto pad = static_cast<size_t>(added > 0 && line > 0 ? line - 1 : line);
  auto file =
      std::make_unique<compiler::SourceFile>(test_.path, std::string(pad, '\n') + versioned);
  compiler::DiagnosticSink sink(20);
  glsl::CheckOptions options;
  options.link = false;
  glsl::CheckShader(stage == "vertex" ? glsl::Stage::Vertex : glsl::Stage::Fragment, {file.get()},
                    options, &sink);
  for (const compiler::Diagnostic& d : sink.diagnostics()) {
    if (d.severity != compiler::Severity::Error) continue;
    compiler::LineCol at = file->Locate(d.range.begin);
    result_.diagnostics.push_back(fmt::format("{}:{}:{}: error: {} [{}]", test_.path, at.line,
                                              at.column, d.message,
                                              d.info != nullptr ? d.info->code : "glsl"));
  }
}

bool Session::BuildGlsl(const std::string& translated_vertex,
                        const std::string& translated_fragment) {
  struct Stage {
    GLenum type;
    std::string name;
    std::string text;
    int line;
    bool translated;
  };
  std::vector<Stage> stages;
  for (const ShaderTestSource& v : test_.vertex_shaders) {
    stages.push_back({GL_VERTEX_SHADER, "vertex", v.text, v.line, false});
  }
  if (test_.vertex_passthrough) {
    stages.push_back({GL_VERTEX_SHADER, "vertex", kPassthrough, test_.passthrough_line, false});
  } else if (test_.vertex_shaders.empty() && !translated_vertex.empty()) {
    stages.push_back({GL_VERTEX_SHADER, "vertex", translated_vertex, 0, true});
  } else if (test_.vertex_shaders.empty() && StateUniforms() && !translated_fragment.empty()) {
    // No fixed-function vertex stage writes the translation's named inputs.
    stages.push_back(
        {GL_VERTEX_SHADER, "vertex", StandInVertexShader(translated_fragment), 0, true});
  }
  for (const ShaderTestSource& f : test_.fragment_shaders) {
    stages.push_back({GL_FRAGMENT_SHADER, "fragment", f.text, f.line, false});
  }
  if (test_.fragment_shaders.empty() && !translated_fragment.empty()) {
    stages.push_back({GL_FRAGMENT_SHADER, "fragment", translated_fragment, 0, true});
  } else if (test_.fragment_shaders.empty() && StateUniforms() && !translated_vertex.empty()) {
    // No fixed-function fragment stage reads the translation's named outputs.
    stages.push_back(
        {GL_FRAGMENT_SHADER, "fragment", StandInFragmentShader(translated_vertex), 0, true});
  }
  if (stages.empty()) return true;

  program_ = gl_.CreateProgram();
  for (const Stage& s : stages) {
    GLuint shader = gl_.CreateShader(s.type);
    const std::string source = s.translated ? s.text : WithVersion(s.text);
    const GLchar* text = source.c_str();
    gl_.ShaderSource(shader, 1, &text, nullptr);
    gl_.CompileShader(shader);
    GLint ok = GL_FALSE;
    gl_.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
      GLint length = 0;
      gl_.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
      std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
      gl_.GetShaderInfoLog(shader, length, nullptr, log.data());
      gl_.DeleteShader(shader);
      result_.status = TestStatus::Fail;
      result_.message =
          s.translated
              ? fmt::format("{}: Mesa rejects arbiter's GLSL translation ({} shader)", test_.path,
                            s.name)
              : fmt::format("{}:{}: the {} shader does not compile", test_.path, s.line, s.name);
      AddLog("mesa: ", log.c_str(), &result_.diagnostics);
      if (!s.translated) AddGlslDiagnostics(s.name, s.text, s.line);
      return false;
    }
    gl_.AttachShader(program_, shader);
    gl_.DeleteShader(shader);  // deleted with the program
  }
  gl_.BindAttribLocation(program_, 0, "piglit_vertex");
  gl_.BindAttribLocation(program_, 1, "piglit_texcoord");
  for (const arbvp::AttributeBinding& a : bindings_.attributes) {
    if (a.location >= 0) {
      gl_.BindAttribLocation(program_, static_cast<GLuint>(a.location), a.name.c_str());
    }
  }
  gl_.LinkProgram(program_);
  GLint linked = GL_FALSE;
  gl_.GetProgramiv(program_, GL_LINK_STATUS, &linked);
  if (linked != GL_TRUE) {
    link_ok_ = false;
    if (ExpectsLinkError(test_)) return true;
    GLint length = 0;
    gl_.GetProgramiv(program_, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    gl_.GetProgramInfoLog(program_, length, nullptr, log.data());
    result_.status = TestStatus::Fail;
    result_.message = fmt::format("{}: the GLSL program does not link", test_.path);
    AddLog("mesa: ", log.c_str(), &result_.diagnostics);
    return false;
  }
  gl_.UseProgram(program_);
  for (const arbvp::SamplerBinding& s : bindings_.samplers) {
    GLint location = gl_.GetUniformLocation(program_, s.name.c_str());
    if (location >= 0) gl_.Uniform1i(location, s.unit);
  }
  return true;
}

bool Session::SetUpPrograms() {
  const bool arb = test_.vertex_program.line != 0 || test_.fragment_program.line != 0;
  std::string vertex;
  std::string fragment;
  if (options_.translate && arb) {
    if ((test_.vertex_program.line != 0 &&
         (!test_.vertex_shaders.empty() || test_.vertex_passthrough)) ||
        (test_.fragment_program.line != 0 && !test_.fragment_shaders.empty())) {
      line_ =
          test_.vertex_program.line != 0 ? test_.vertex_program.line : test_.fragment_program.line;
      Error("an ARB program and a GLSL shader for the same stage cannot be translated together");
    }
    if (!TranslateArb(&vertex, &fragment)) return false;
  } else {
    if (test_.vertex_program.line != 0 &&
        !LoadArb(arbvp::ProgramKind::Vertex, test_.vertex_program)) {
      return false;
    }
    if (test_.fragment_program.line != 0 &&
        !LoadArb(arbvp::ProgramKind::Fragment, test_.fragment_program)) {
      return false;
    }
  }
  return BuildGlsl(vertex, fragment);
}

void Session::UploadTranslationState() {
  if (!translated_ || program_ == 0 || !link_ok_) return;
  if (StateUniforms()) {
    UploadStateUniforms();
    return;
  }
  for (const arbvp::ParameterArray& p : bindings_.parameters) {
    GLint location = gl_.GetUniformLocation(program_, p.name.c_str());
    if (location < 0) continue;
    std::vector<float> values(static_cast<size_t>(p.size) * 4, 0.0f);
    for (int i = 0; i < p.size; ++i) {
      auto it = parameters_.find({p.target, p.local, i});
      if (it != parameters_.end()) {
        std::copy(it->second.begin(), it->second.end(), values.begin() + i * 4);
      }
    }
    gl_.Uniform4fv(location, p.size, values.data());
  }
  // GL state without a GLSL built-in: program matrices (read back from GL) and clip planes
  // past gl_ClipPlane's guaranteed six; the others (modelview[n > 0], palette) do not exist
  // in Mesa and keep their identity.
  for (const arbvp::StateUniform& s : bindings_.state) {
    GLint location = gl_.GetUniformLocation(program_, s.name.c_str());
    if (location < 0) continue;
    int index = 0;
    if (s.type == "vec4" && std::sscanf(s.binding.c_str(), "state.clip[%d]", &index) == 1) {
      GLdouble plane[4] = {0, 0, 0, 0};
      gl_.GetClipPlane(static_cast<GLenum>(GL_CLIP_PLANE0 + index), plane);
      const float value[4] = {static_cast<float>(plane[0]), static_cast<float>(plane[1]),
                              static_cast<float>(plane[2]), static_cast<float>(plane[3])};
      gl_.Uniform4fv(location, 1, value);
      continue;
    }
    glm::mat4 m(1.0f);
    if (std::sscanf(s.binding.c_str(), "state.matrix.program[%d]", &index) == 1) {
      GLint mode = GL_MODELVIEW;
      gl_.GetIntegerv(GL_MATRIX_MODE, &mode);
      gl_.MatrixMode(static_cast<GLenum>(GL_MATRIX0_ARB + index));
      gl_.GetFloatv(GL_CURRENT_MATRIX_ARB, glm::value_ptr(m));
      gl_.MatrixMode(static_cast<GLenum>(mode));
    }
    if (s.binding.find(".inverse") != std::string::npos) m = glm::inverse(m);
    gl_.UniformMatrix4fv(location, 1, GL_FALSE, glm::value_ptr(m));
  }
}

}  // namespace arbiter::runtime::shader_test
