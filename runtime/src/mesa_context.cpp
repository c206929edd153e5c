// MesaContext on OSMesa: context creation, GLSL compile and link, ARB program loading.
#include <GL/osmesa.h>
#include <fmt/format.h>

#include <climits>
#include <cstdlib>
#include <mutex>
#include <sstream>

#include "arbiter/runtime/mesa.h"
#include "gl_api.h"
#include "osmesa_library.h"

namespace arbiter::runtime {
namespace {

// The colour buffer the context draws into; nothing is drawn yet, so it stays tiny.
constexpr GLsizei kBufferSize = 16;

std::string GlErrorText(GLenum error) {
  const char* name = "";
  switch (error) {
    case GL_INVALID_ENUM:
      name = " (GL_INVALID_ENUM)";
      break;
    case GL_INVALID_VALUE:
      name = " (GL_INVALID_VALUE)";
      break;
    case GL_INVALID_OPERATION:
      name = " (GL_INVALID_OPERATION)";
      break;
    case GL_OUT_OF_MEMORY:
      name = " (GL_OUT_OF_MEMORY)";
      break;
    default:
      break;
  }
  return fmt::format("GL error 0x{:04x}{}", error, name);
}

class OsMesaContext final : public MesaContext {
 public:
  OsMesaContext(const OsMesaLibrary* lib, OSMesaContext context, std::string driver)
      : lib_(lib),
        context_(context),
        driver_(std::move(driver)),
        buffer_(static_cast<size_t>(kBufferSize) * kBufferSize * 4) {}

  ~OsMesaContext() override {
    std::lock_guard<std::mutex> lock(mutex_);
    lib_->DestroyContext(context_);
  }

  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  // Makes the context current, loads the entry points and reads the context's strings.
  bool Init(std::string* error) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!MakeCurrent()) {
      *error = "OSMesaMakeCurrent failed";
      return false;
    }
    bool ok = LoadGlApi(&gl_, error);
    if (ok) {
      const std::string renderer = GetString(GL_RENDERER);
      description_ = fmt::format("{}, {}", renderer, GetString(GL_VERSION));
      std::istringstream words(GetString(GL_EXTENSIONS));
      for (std::string word; words >> word;) extensions_.push_back(word);
      // OSMesa creates its gallium screen at the first context and keeps it: a later context
      // runs that driver whatever GALLIUM_DRIVER says now.
      if (renderer.rfind(driver_, 0) != 0) {
        *error = fmt::format(
            "OSMesa runs '{}' in this process, not '{}' (the driver is chosen once per process)",
            renderer, driver_);
        ok = false;
      }
      DrainErrors();
    }
    Release();
    return ok;
  }

  const std::string& driver() const override { return driver_; }
  const std::string& description() const override { return description_; }
  const std::vector<std::string>& extensions() const override { return extensions_; }

  MesaVerdict CompileGlsl(glsl::Stage stage, const std::vector<std::string_view>& sources,
                          bool link) override {
    MesaVerdict verdict;
    std::vector<const GLchar*> strings;
    std::vector<GLint> lengths;
    for (std::string_view source : sources) {
      if (source.size() > static_cast<size_t>(INT_MAX)) {
        verdict.failure = "a source string is longer than GL can take (2 GiB)";
        return verdict;
      }
      strings.push_back(source.data());
      lengths.push_back(static_cast<GLint>(source.size()));
    }
    std::lock_guard<std::mutex> lock(mutex_);
    if (!MakeCurrent()) {
      verdict.failure = "OSMesaMakeCurrent failed";
      return verdict;
    }
    DrainErrors();
    const GLuint shader =
        gl_.CreateShader(stage == glsl::Stage::Vertex ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER);
    gl_.ShaderSource(shader, static_cast<GLsizei>(strings.size()), strings.data(), lengths.data());
    gl_.CompileShader(shader);
    GLint status = GL_FALSE;
    gl_.GetShaderiv(shader, GL_COMPILE_STATUS, &status);
    verdict.compiled = status == GL_TRUE;
    verdict.compile_log = ShaderLog(shader);
    verdict.accepted = verdict.compiled;
    if (verdict.compiled && link) {
      const GLuint program = gl_.CreateProgram();
      gl_.AttachShader(program, shader);
      gl_.LinkProgram(program);
      status = GL_FALSE;
      gl_.GetProgramiv(program, GL_LINK_STATUS, &status);
      verdict.linked = status == GL_TRUE;
      verdict.link_log = ProgramLog(program);
      verdict.accepted = verdict.linked;
      gl_.DeleteProgram(program);
    }
    gl_.DeleteShader(shader);
    const GLenum error = gl_.GetError();
    if (error != GL_NO_ERROR) verdict.failure = GlErrorText(error);
    DrainErrors();
    Release();
    return verdict;
  }

  MesaVerdict LoadArbProgram(arbvp::ProgramKind kind, std::string_view text) override {
    MesaVerdict verdict;
    if (text.size() > static_cast<size_t>(INT_MAX)) {
      verdict.failure = "the program is longer than GL can take (2 GiB)";
      return verdict;
    }
    const GLenum target =
        kind == arbvp::ProgramKind::Vertex ? GL_VERTEX_PROGRAM_ARB : GL_FRAGMENT_PROGRAM_ARB;
    std::lock_guard<std::mutex> lock(mutex_);
    if (!MakeCurrent()) {
      verdict.failure = "OSMesaMakeCurrent failed";
      return verdict;
    }
    DrainErrors();
    GLuint id = 0;
    gl_.GenProgramsARB(1, &id);
    gl_.BindProgramARB(target, id);
    gl_.ProgramStringARB(target, GL_PROGRAM_FORMAT_ASCII_ARB, static_cast<GLsizei>(text.size()),
                         text.data());
    const GLenum error = gl_.GetError();
    GLint position = -1;
    gl_.GetIntegerv(GL_PROGRAM_ERROR_POSITION_ARB, &position);
    verdict.error_position = position;
    verdict.error_string = GetString(GL_PROGRAM_ERROR_STRING_ARB);
    verdict.accepted = error == GL_NO_ERROR;
    if (error != GL_NO_ERROR && error != GL_INVALID_OPERATION) {
      verdict.failure = GlErrorText(error);
    }
    gl_.BindProgramARB(target, 0);
    gl_.DeleteProgramsARB(1, &id);
    DrainErrors();
    Release();
    return verdict;
  }

 private:
  // Binds the context to the calling thread (callers hold mutex_).
  bool MakeCurrent() {
    return lib_->MakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kBufferSize,
                             kBufferSize) == GL_TRUE;
  }

  // Unbinds it again, so that no other thread's binding outlives the call.
  void Release() { lib_->MakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0); }

  void DrainErrors() {
    // GL keeps one flag per error kind: a handful of calls clears them all.
    for (int i = 0; i < 16 && gl_.GetError() != GL_NO_ERROR; ++i) {
    }
  }

  std::string GetString(GLenum name) {
    const GLubyte* raw = gl_.GetString(name);
    return raw != nullptr ? reinterpret_cast<const char*>(raw) : "";
  }

  std::string ShaderLog(GLuint shader) {
    GLint length = 0;
    gl_.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    if (length <= 1) return "";
    std::string log(static_cast<size_t>(length), '\0');
    GLsizei written = 0;
    gl_.GetShaderInfoLog(shader, length, &written, log.data());
    log.resize(static_cast<size_t>(written));
    return log;
  }

  std::string ProgramLog(GLuint program) {
    GLint length = 0;
    gl_.GetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    if (length <= 1) return "";
    std::string log(static_cast<size_t>(length), '\0');
    GLsizei written = 0;
    gl_.GetProgramInfoLog(program, length, &written, log.data());
    log.resize(static_cast<size_t>(written));
    return log;
  }

  std::mutex mutex_;
  const OsMesaLibrary* lib_;
  OSMesaContext context_;
  std::string driver_;
  std::vector<GLubyte> buffer_;
  GlApi gl_;
  std::string description_;
  std::vector<std::string> extensions_;
};

}  // namespace

bool IsSupportedMesaDriver(std::string_view name) {
  return name == "softpipe" || name == "llvmpipe";
}

std::string FirstErrorLine(const MesaVerdict& verdict) {
  std::string first_line;
  for (const std::string* log : {&verdict.compile_log, &verdict.link_log, &verdict.error_string}) {
    std::istringstream lines(*log);
    for (std::string line; std::getline(lines, line);) {
      while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t' ||
                               line.back() == '\0')) {
        line.pop_back();
      }
      const size_t start = line.find_first_not_of(" \t");
      if (start == std::string::npos) continue;
      line.erase(0, start);
      if (line.find("error") != std::string::npos) return line;
      if (first_line.empty()) first_line = line;
    }
  }
  return first_line;
}

std::unique_ptr<MesaContext> CreateMesaContext(const MesaOptions& options, std::string* error) {
  if (!IsSupportedMesaDriver(options.driver)) {
    *error = fmt::format("unsupported Mesa driver '{}' (softpipe or llvmpipe)", options.driver);
    return nullptr;
  }
  // Mesa reads its configuration from the environment; these are the only two settings.
  setenv("GALLIUM_DRIVER", options.driver.c_str(), 1);
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  // Mesa (and LLVM with it) is loaded only now, on the first context.
  const OsMesaLibrary* lib = LoadOsMesa(error);
  if (lib == nullptr) return nullptr;
  OSMesaContext context = CreateCompatibilityContext(*lib);
  if (context == nullptr) {
    *error = fmt::format("OSMesaCreateContextAttribs failed ({}, compatibility profile)",
                         options.driver);
    return nullptr;
  }
  auto mesa = std::make_unique<OsMesaContext>(lib, context, options.driver);
  if (!mesa->Init(error)) return nullptr;
  return mesa;
}

}  // namespace arbiter::runtime
