// One shader test's run: a clean state on the worker's reused context, requirements,
// programs, the commands, the picture, and everything put back for the next test.
#include "shader_test/session.h"

#include <fmt/format.h>

#include "shader_test/gl_names.h"
#include "shader_test/words.h"

namespace arbiter::runtime::shader_test {
namespace {

constexpr int kDefaultWindow = 250;
// piglit's tolerance for an 8-bit channel: 3 / 2^8 (piglit_set_tolerance_for_bits).
constexpr float kDefaultTolerance = 3.0f / 256.0f;
constexpr int kMatrixUnits = 8;  // texture matrices and program matrices reset per test

}  // namespace

bool Session::WindowSize(const ShaderTest& test, int* width, int* height, std::string* error) {
  *width = kDefaultWindow;
  *height = kDefaultWindow;
  for (const ShaderTestLine& r : test.require) {
    std::vector<std::string> words = Words(r.text);
    if (words.empty() || words[0] != "SIZE") continue;
    if (words.size() != 3 || !ParseInt(words[1], width) || !ParseInt(words[2], height) ||
        *width < 1 || *height < 1 || *width > 4096 || *height > 4096) {
      *error =
          fmt::format("{}:{}: SIZE takes a width and a height from 1 to 4096", test.path, r.line);
      return false;
    }
  }
  return true;
}

void Session::Error(std::string message) const { throw TestError{line_, std::move(message)}; }

GLenum Session::Enum(const std::string& name) const {
  GLenum value = 0;
  if (GlEnumByName(name, &value)) return value;
  unsigned number = 0;
  if (name.rfind("0x", 0) == 0 && ParseUint(name, &number)) return number;
  Error(fmt::format("unknown GL enum '{}'", name));
}

float Session::Float(const std::vector<std::string>& words, size_t i) const {
  float value = 0.0f;
  if (i >= words.size()) Error("missing number");
  if (!ParseFloat(words[i], &value)) Error(fmt::format("'{}' is not a number", words[i]));
  return value;
}

int Session::Int(const std::vector<std::string>& words, size_t i) const {
  int value = 0;
  if (i >= words.size()) Error("missing integer");
  if (!ParseInt(words[i], &value)) Error(fmt::format("'{}' is not an integer", words[i]));
  return value;
}

void Session::CheckGlError(const std::string& what) {
  GLenum error = gl_.GetError();
  if (error == GL_NO_ERROR) return;
  for (int i = 0; i < 16 && gl_.GetError() != GL_NO_ERROR; ++i) {
  }
  Error(fmt::format("{} raised {}", what, exec::GlErrorName(error)));
}

void Session::Run(std::vector<uint8_t>* image) {
  result_.status = TestStatus::Pass;
  tolerance_.fill(kDefaultTolerance);
  try {
    if (std::string unmet = UnmetRequirement(); !unmet.empty()) {
      result_.status = TestStatus::Skip;
      result_.message = unmet;
      return;
    }
  } catch (const TestError& e) {
    result_.status = TestStatus::Fail;
    result_.message = fmt::format("{}:{}: {}", test_.path, e.line, e.message);
    return;
  }
  for (int i = 0; i < 16 && gl_.GetError() != GL_NO_ERROR; ++i) {
  }
  // Everything a command can change is restored afterwards: the attribute stacks hold the
  // fixed-function state; matrices, programs, textures and env parameters are reset here.
  gl_.PushAttrib(GL_ALL_ATTRIB_BITS);
  gl_.PushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, window_.framebuffer);
  gl_.Viewport(0, 0, window_.width, window_.height);
  gl_.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  gl_.ClearDepth(1.0);
  gl_.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  auto reset_matrices = [&] {
    for (GLenum mode : {GLenum{GL_PROJECTION}, GLenum{GL_MODELVIEW}}) {
      gl_.MatrixMode(mode);
      gl_.LoadIdentity();
    }
    for (int i = 0; i < kMatrixUnits; ++i) {
      gl_.ActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + i));
      gl_.MatrixMode(GL_TEXTURE);
      gl_.LoadIdentity();
      gl_.MatrixMode(static_cast<GLenum>(GL_MATRIX0_ARB + i));
      gl_.LoadIdentity();
    }
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.MatrixMode(GL_MODELVIEW);
  };
  reset_matrices();

  try {
    if (SetUpPrograms()) {
      for (const ShaderTestLine& command : test_.commands) {
        line_ = command.line;
        Execute(command);
        CheckGlError(fmt::format("'{}'", command.text));
      }
    }
    // piglit passes such a test when its programs link; say that this is all it checked.
    if (test_.commands.empty() && result_.status == TestStatus::Pass) {
      result_.warnings.push_back(
          "no [test] command: only that the programs compile and link was checked");
    }
  } catch (const TestError& e) {
    result_.status = TestStatus::Fail;
    if (!result_.message.empty()) result_.message += "\n";
    result_.message += fmt::format("{}:{}: {}", test_.path, e.line, e.message);
  }
  if (image != nullptr) {
    image->assign(static_cast<size_t>(window_.width) * static_cast<size_t>(window_.height) * 4, 0);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, window_.framebuffer);
    gl_.ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_.ReadPixels(0, 0, window_.width, window_.height, GL_RGBA, GL_UNSIGNED_BYTE, image->data());
  }

  // Put the context back as the next test expects to find it.
  gl_.UseProgram(0);
  if (program_ != 0) gl_.DeleteProgram(program_);
  gl_.BindProgramARB(GL_VERTEX_PROGRAM_ARB, 0);
  gl_.BindProgramARB(GL_FRAGMENT_PROGRAM_ARB, 0);
  for (GLuint id : arb_programs_) {
    if (id != 0) gl_.DeleteProgramsARB(1, &id);
  }
  if (!textures_.empty()) {
    gl_.DeleteTextures(static_cast<GLsizei>(textures_.size()), textures_.data());
  }
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  for (const auto& [key, value] : parameters_) {
    if (key.local) continue;
    gl_.ProgramEnvParameter4fvARB(
        key.target == arbvp::ProgramKind::Vertex ? GL_VERTEX_PROGRAM_ARB : GL_FRAGMENT_PROGRAM_ARB,
        static_cast<GLuint>(key.index), zero);
  }
  reset_matrices();
  gl_.PopClientAttrib();
  gl_.PopAttrib();
  for (int i = 0; i < 16 && gl_.GetError() != GL_NO_ERROR; ++i) {
  }
}

void Session::ProbeFailed(const std::string& message, bool warn) {
  std::string located = fmt::format("{}:{}: {}", test_.path, line_, message);
  if (warn) {
    result_.warnings.push_back(std::move(located));
    return;
  }
  result_.status = TestStatus::Fail;
  if (!result_.message.empty()) result_.message += "\n";
  result_.message += located;
}

}  // namespace arbiter::runtime::shader_test
