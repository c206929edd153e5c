// One shader test on one GL context: requirements, programs, then the [test] commands in
// order. The pieces live in files named for them: session.cpp (the run and its state),
// programs.cpp (ARB programs, GLSL shaders, --translate), commands.cpp (the command table),
// draw.cpp (rectangles and vertex data), probe.cpp, textures.cpp, require.cpp.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "arbiter/arbvp/check.h"
#include "arbiter/glstate/gl_state.h"
#include "arbiter/runtime/shader_test.h"
#include "exec/context.h"
#include "exec/exec_gl.h"

namespace arbiter::runtime::shader_test {

// What a worker's context offers, read once.
struct ContextInfo {
  std::string renderer;
  double gl_version = 0.0;    // 4.5
  double glsl_version = 0.0;  // 4.5 (from "4.50")
  std::set<std::string> extensions;
};

// The colour (RGBA8) and depth-stencil framebuffer a test draws into.
struct Window {
  int width = 0;
  int height = 0;
  GLuint framebuffer = 0;
  std::array<GLuint, 2> renderbuffers{};
};

// Thrown by a command on a malformed line or an unusable request: the test fails with
// "file:line: message".
struct TestError {
  int line = 0;
  std::string message;
};

// program.env / program.local values recorded for --translate (uploaded to the
// translation's uniform arrays before each draw).
struct ParameterKey {
  arbvp::ProgramKind target;
  bool local;
  int index;
  bool operator<(const ParameterKey& o) const {
    return std::tie(target, local, index) < std::tie(o.target, o.local, o.index);
  }
};

// The ARB spelling of a fixed-function [vertex data] column ("gl_MultiTexCoord2" ->
// "vertex.texcoord[2]"), or "" (translate_state.cpp).
std::string FixedFunctionBinding(const std::string& column);

class Session {
 public:
  Session(const exec::ExecGl& gl, const ContextInfo& info, Window* window,
          const RunOptions& options, const ShaderTest& test, ShaderTestResult* result)
      : gl_(gl), info_(info), window_(*window), options_(options), test_(test), result_(*result) {}

  // Runs the test into `result`: status, message, diagnostics. `image` (when not null)
  // receives the final picture as RGBA8, bottom row first.
  void Run(std::vector<uint8_t>* image);

  // The window size the test asks for (SIZE w h; default 250 x 250).
  static bool WindowSize(const ShaderTest& test, int* width, int* height, std::string* error);

 private:
  // require.cpp: "" when every requirement holds, else the first unmet one.
  std::string UnmetRequirement();

  // programs.cpp
  bool SetUpPrograms();  // false: the test failed (result filled)
  bool LoadArb(arbvp::ProgramKind kind, const ShaderTestSource& source);
  bool BuildGlsl(const std::string& translated_vertex, const std::string& translated_fragment);
  bool TranslateArb(std::string* vertex, std::string* fragment);
  bool CheckArb(arbvp::ProgramKind kind, const ShaderTestSource& source,
                std::unique_ptr<compiler::SourceFile>* file, arbvp::CheckResult* checked);
  void UploadTranslationState();  // before each draw under --translate
  // translate_state.cpp: --translate to a target that reads state from uniforms
  // (--translate=glsl330, es300, ...).
  bool StateUniforms() const { return translated_ && bindings_.state_uniforms; }
  // The texture target a test's 1D or rectangle texture on `unit` is made with: GL_TEXTURE_2D
  // where the translation emulates it with a 2D sampler (arbvp::UploadsAs2D), else `target`.
  GLenum TranslatedTexTarget(GLenum target, int unit) const;
  // Whether the translation reads enable `cap` as a uniform (clip[n].enabled, for a dialect
  // without clip distances or their enables): GL's own stays off, as on an ES context.
  bool EnableIsUniform(GLenum cap) const;
  int AttributeLocation(const std::string& binding) const;  // -1: the program has none
  std::string StandInFragmentShader(const std::string& vertex) const;
  std::string StandInVertexShader(const std::string& fragment);  // adds to bindings_
  void UploadStateUniforms();
  void TrackState(const std::string& command, const std::vector<std::string>& words);
  void AddGlslDiagnostics(const std::string& stage, const std::string& text, int line);
  // The "#version N\n" shader_runner puts before a shader without one ("" for 1.10), and the
  // shader text with it.
  std::string VersionDirective() const;
  std::string WithVersion(const std::string& text) const;

  // commands.cpp
  void Execute(const ShaderTestLine& command);
  void SetParameter(const std::vector<std::string>& words);
  void SetUniform(const std::vector<std::string>& words);
  void SetState(const std::string& command, const std::vector<std::string>& words);

  // draw.cpp
  void DrawRect(float x, float y, float w, float h, const float* tex);
  void DrawArrays(const std::vector<std::string>& words);
  void BeforeDraw();

  // probe.cpp
  void Probe(const std::vector<std::string>& words, bool relative, bool warn);
  void ProbeDepth(const std::vector<std::string>& words);
  void ProbeFailed(const std::string& message, bool warn);

  // textures.cpp
  void Texture(const std::vector<std::string>& words);
  void TexParameter(const std::vector<std::string>& words);

  GLenum Enum(const std::string& name) const;  // or TestError
  float Float(const std::vector<std::string>& words, size_t i) const;
  int Int(const std::vector<std::string>& words, size_t i) const;
  [[noreturn]] void Error(std::string message) const;
  void CheckGlError(const std::string& what);

  const exec::ExecGl& gl_;
  const ContextInfo& info_;
  Window& window_;
  const RunOptions& options_;
  const ShaderTest& test_;
  ShaderTestResult& result_;

  int line_ = 0;  // the command being executed
  bool failed_ = false;
  std::array<float, 4> tolerance_{};
  GLuint program_ = 0;  // the GLSL program (test's shaders or --translate's translation)
  std::array<GLuint, 2> arb_programs_{};  // vertex, fragment
  bool link_ok_ = true;
  std::vector<GLuint> textures_;
  std::map<ParameterKey, std::array<float, 4>> parameters_;
  arbvp::BindingMap bindings_;  // the translation's, under --translate
  // The GL state the commands set, as a port keeps it (docs/glstate.md): under a --translate
  // target without built-in state it reaches the translation only through its uniforms.
  glstate::GlState state_;
  std::map<std::string, std::array<float, 4>> current_;  // current attributes by ARB spelling
  bool translated_ = false;
};

}  // namespace arbiter::runtime::shader_test
