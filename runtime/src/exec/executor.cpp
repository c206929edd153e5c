// ArbExecutor on Mesa: one context, and per run the rewritten programs (program_rewrite.h),
// the GL state, textures and points, then the readback of every attachment.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <sstream>

#include "arbiter/runtime/exec.h"
#include "arbiter/runtime/mesa.h"
#include "exec/context.h"
#include "exec/draw.h"
#include "exec/exec_gl.h"
#include "exec/framebuffer.h"
#include "exec/program_cache.h"
#include "exec/program_rewrite.h"
#include "exec/state_upload.h"
#include "exec/textures.h"
#include "exec_glsl/glsl_run.h"

namespace arbiter::runtime {
namespace {

using exec::ExecGl;

// GL keeps one flag per error kind: a handful of calls clears them all.
void DrainErrors(const ExecGl& gl) {
  for (int i = 0; i < 16 && gl.GetError() != GL_NO_ERROR; ++i) {
  }
}

std::string GetString(const ExecGl& gl, GLenum name) {
  const GLubyte* raw = gl.GetString(name);
  return raw != nullptr ? reinterpret_cast<const char*>(raw) : "";
}

// The line of `text` that holds byte `position`, for error messages.
std::string LineAt(const std::string& text, GLint position) {
  if (position < 0 || static_cast<size_t>(position) >= text.size()) return "";
  size_t begin = text.rfind('\n', static_cast<size_t>(position));
  begin = begin == std::string::npos ? 0 : begin + 1;
  size_t end = text.find('\n', static_cast<size_t>(position));
  return text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

class MesaArbExecutor final : public ArbExecutor {
 public:
  MesaArbExecutor(std::unique_ptr<exec::GlContext> context, const ExecGl& gl,
                  std::string description, const exec::ContextLimits& limits)
      : context_(std::move(context)),
        gl_(gl),
        description_(std::move(description)),
        limits_(limits) {}
  ~MesaArbExecutor() override = default;

  const std::string& description() const override { return description_; }

  bool Run(const ArbPrograms& programs, const arbvp::ExecInputs& inputs,
           std::vector<arbvp::VectorResult>* results, std::string* error) override {
    results->clear();
    exec::RunPlan plan;
    if (!exec::PlanRun(programs, limits_, &plan, error)) return false;
    if (!context_->MakeCurrent()) {
      *error = "cannot make the GL context current";
      return false;
    }
    DrainErrors(gl_);
    bool ok = RunPlan(plan, programs, inputs, results, error);
    DrainErrors(gl_);
    context_->Release();
    if (!ok) results->clear();
    return ok;
  }

  bool RunTranslated(const ArbPrograms& programs, const arbvp::EmitOptions& emit,
                     const arbvp::ExecInputs& inputs, std::vector<arbvp::VectorResult>* results,
                     std::string* error) override {
    results->clear();
    if (!context_->MakeCurrent()) {
      *error = "cannot make the GL context current";
      return false;
    }
    DrainErrors(gl_);
    bool ok = exec::RunGlslTranslation(gl_, limits_, programs, emit, inputs, &glsl_cache_, results,
                                       error);
    DrainErrors(gl_);
    context_->Release();
    return ok;
  }

 private:
  // Checks for a GL error after `step`.
  bool Check(const char* step, std::string* error) {
    const GLenum code = gl_.GetError();
    if (code == GL_NO_ERROR) return true;
    *error = fmt::format("{} raised {}", step, exec::GlErrorName(code));
    return false;
  }

  bool RunPlan(const exec::RunPlan& plan, const ArbPrograms& programs,
               const arbvp::ExecInputs& inputs, std::vector<arbvp::VectorResult>* results,
               std::string* error) {
    const size_t count = inputs.vectors.size();
    results->assign(count, arbvp::VectorResult{});
    if (count == 0 || plan.passes.empty()) return true;
    const int width = arbvp::kFramebufferWidth;
    const int height =
        static_cast<int>((count + static_cast<size_t>(width) - 1) / static_cast<size_t>(width));
    size_t attachments = 1;
    for (const exec::Pass& pass : plan.passes) {
      attachments = std::max(attachments, pass.attachments.size());
    }

    SetFixedState(plan.mode);
    exec::UploadGlState(gl_, inputs.state);
    if (!Check("setting the GL state", error)) return false;
    exec::UploadEnvParameters(gl_, GL_VERTEX_PROGRAM_ARB, inputs.vertex_params.env);
    exec::UploadEnvParameters(gl_, GL_FRAGMENT_PROGRAM_ARB, inputs.fragment_params.env);
    if (!Check("setting program.env parameters", error)) return false;
    std::vector<GLuint> textures;
    bool ok = exec::UploadTextures(gl_, inputs.textures, &textures, error) &&
              Check("creating the textures", error);
    if (ok) {
      exec::Framebuffer framebuffer(gl_);
      ok = framebuffer.Create(width, height, static_cast<int>(attachments), error) &&
           Check("creating the framebuffer", error);
      std::vector<std::vector<float>> values(plan.outputs.size());
      std::vector<float> alive;
      for (size_t p = 0; ok && p < plan.passes.size(); ++p) {
        ok = RunPass(plan, plan.passes[p], programs, inputs, width, height, &framebuffer, &values,
                     &alive, error);
      }
      if (ok) exec::CollectResults(plan, values, alive, nullptr, results);
    }
    exec::DeleteTextures(gl_, &textures);
    return ok && Check("cleaning up", error);
  }

  // State every run needs: unclamped colours, programs on, points of the program's size.
  // A pair keeps GL's vertex colour clamping (on by default: GL 2.0 2.14.6; ARBvp 2.14.3.4
  // clamps result.color on its way to rasterisation), as the reference interpreter does; a
  // fragment program alone reads the model's fragment colours unclamped, so the generated
  // vertex program must pass them through unchanged.
  void SetFixedState(exec::RunMode mode) {
    gl_.ClampColorARB(GL_CLAMP_VERTEX_COLOR_ARB, mode == exec::RunMode::Pair ? GL_TRUE : GL_FALSE);
    gl_.ClampColorARB(GL_CLAMP_FRAGMENT_COLOR_ARB, GL_FALSE);
    gl_.ClampColorARB(GL_CLAMP_READ_COLOR_ARB, GL_FALSE);
    gl_.Enable(GL_VERTEX_PROGRAM_ARB);
    gl_.Enable(GL_FRAGMENT_PROGRAM_ARB);
    gl_.Enable(GL_VERTEX_PROGRAM_POINT_SIZE_ARB);
    gl_.Disable(GL_DEPTH_TEST);
    gl_.Disable(GL_BLEND);
    gl_.Disable(GL_POINT_SMOOTH);
    gl_.Disable(GL_POINT_SPRITE_ARB);
    gl_.Disable(GL_CULL_FACE);
    gl_.Disable(GL_SCISSOR_TEST);
    gl_.Disable(GL_ALPHA_TEST);
    gl_.Disable(GL_FOG);
  }

  // Binds the program compiled from `text`, from the cache or loaded now.
  bool BindProgram(GLenum target, const std::string& text, std::string* error) {
    const std::string key = (target == GL_VERTEX_PROGRAM_ARB ? "v" : "f") + text;
    GLuint id = cache_.Find(key);
    if (id != 0) {
      gl_.BindProgramARB(target, id);
      return true;
    }
    if (!LoadProgram(target, text, &id, error)) {
      gl_.BindProgramARB(target, 0);
      gl_.DeleteProgramsARB(1, &id);
      return false;
    }
    const GLuint evicted = cache_.Add(key, id);
    if (evicted != 0) gl_.DeleteProgramsARB(1, &evicted);
    return true;
  }

  // Loads one program; on rejection says why, with the line of the rewritten text.
  bool LoadProgram(GLenum target, const std::string& text, GLuint* id, std::string* error) {
    gl_.GenProgramsARB(1, id);
    gl_.BindProgramARB(target, *id);
    gl_.ProgramStringARB(target, GL_PROGRAM_FORMAT_ASCII_ARB, static_cast<GLsizei>(text.size()),
                         text.data());
    const GLenum code = gl_.GetError();
    if (code == GL_NO_ERROR) return true;
    GLint position = -1;
    gl_.GetIntegerv(GL_PROGRAM_ERROR_POSITION_ARB, &position);
    std::string message = GetString(gl_, GL_PROGRAM_ERROR_STRING_ARB);
    while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back()))) {
      message.pop_back();  // Mesa ends the message with a newline
    }
    *error = fmt::format("mesa rejected the {} program: {} (at '{}')",
                         target == GL_VERTEX_PROGRAM_ARB ? "vertex" : "fragment", message,
                         LineAt(text, position));
    if (code != GL_INVALID_OPERATION) *error += ", raising " + exec::GlErrorName(code);
    return false;
  }

  bool RunPass(const exec::RunPlan& plan, const exec::Pass& pass, const ArbPrograms& programs,
               const arbvp::ExecInputs& inputs, int width, int height,
               exec::Framebuffer* framebuffer, std::vector<std::vector<float>>* values,
               std::vector<float>* alive, std::string* error) {
    bool ok = BindProgram(GL_VERTEX_PROGRAM_ARB, pass.vertex_text, error);
    if (ok && programs.vertex != nullptr) {
      exec::UploadLocalParameters(gl_, GL_VERTEX_PROGRAM_ARB, inputs.vertex_params.local);
    }
    ok = ok && BindProgram(GL_FRAGMENT_PROGRAM_ARB, pass.fragment_text, error);
    if (ok && programs.fragment != nullptr) {
      exec::UploadLocalParameters(gl_, GL_FRAGMENT_PROGRAM_ARB, inputs.fragment_params.local);
    }
    ok = ok && Check("setting program.local parameters", error);
    if (ok) {
      framebuffer->Begin(static_cast<int>(pass.attachments.size()));
      exec::DrawPoints(gl_, plan, inputs, width, height);
      ok = Check("drawing the points", error);
    }
    for (size_t a = 0; ok && a < pass.attachments.size(); ++a) {
      const int slot = pass.attachments[a];
      if (slot == exec::kAliveFlag && !alive->empty()) continue;  // one pass says it
      framebuffer->Read(static_cast<int>(a),
                        slot == exec::kAliveFlag ? alive : &(*values)[static_cast<size_t>(slot)]);
      ok = Check("reading the framebuffer back", error);
    }
    gl_.BindProgramARB(GL_VERTEX_PROGRAM_ARB, 0);
    gl_.BindProgramARB(GL_FRAGMENT_PROGRAM_ARB, 0);
    return ok;
  }

  std::unique_ptr<exec::GlContext> context_;
  ExecGl gl_;
  std::string description_;
  exec::ContextLimits limits_;
  // The rewritten programs of the last few runs (a program, its passes, a pair's two).
  exec::ProgramCache cache_{8};
  exec::GlslCache glsl_cache_;
};

bool HasExtension(const std::string& extensions, const std::string& name) {
  std::istringstream words(extensions);
  for (std::string word; words >> word;) {
    if (word == name) return true;
  }
  return false;
}

}  // namespace

bool ParseBackend(std::string_view name, Backend* backend) {
  if (name == "osmesa") {
    *backend = Backend::OSMesa;
  } else if (name == "egl") {
    *backend = Backend::Egl;
  } else {
    return false;
  }
  return true;
}

std::string_view BackendName(Backend backend) { return backend == Backend::Egl ? "egl" : "osmesa"; }

std::unique_ptr<ArbExecutor> CreateArbExecutor(const ExecOptions& options, std::string* error) {
  if (!IsSupportedMesaDriver(options.driver)) {
    *error = fmt::format("unsupported Mesa driver '{}' (softpipe or llvmpipe)", options.driver);
    return nullptr;
  }
  exec::SetMesaEnvironment(options.driver);
  std::unique_ptr<exec::GlContext> context = options.backend == Backend::Egl
                                                 ? exec::CreateEglContext(error)
                                                 : exec::CreateOsMesaContext(error);
  ExecGl gl;
  if (context == nullptr ||
      !exec::MakeCurrentAndLoad(context.get(), std::string(BackendName(options.backend)), &gl,
                                error)) {
    return nullptr;
  }
  const std::string renderer = GetString(gl, GL_RENDERER);
  const std::string description =
      fmt::format("{}, {} ({})", renderer, GetString(gl, GL_VERSION), BackendName(options.backend));
  const std::string extensions = GetString(gl, GL_EXTENSIONS);
  exec::ContextLimits limits;
  gl.GetIntegerv(GL_MAX_DRAW_BUFFERS_ARB, &limits.max_draw_buffers);
  gl.GetProgramivARB(GL_VERTEX_PROGRAM_ARB, GL_MAX_PROGRAM_ENV_PARAMETERS_ARB,
                     &limits.max_vertex_env);
  DrainErrors(gl);
  context->Release();
  // Mesa creates its gallium screen once and keeps it: a later context runs that driver
  // whatever GALLIUM_DRIVER says now.
  if (renderer.rfind(options.driver, 0) != 0) {
    *error = fmt::format(
        "{} runs '{}' in this process, not '{}' (the driver is chosen once per process)",
        BackendName(options.backend), renderer, options.driver);
    return nullptr;
  }
  for (const char* needed :
       {"GL_ARB_vertex_program", "GL_ARB_fragment_program", "GL_ARB_color_buffer_float",
        "GL_ARB_texture_float", "GL_ARB_draw_buffers", "GL_ARB_framebuffer_object"}) {
    if (!HasExtension(extensions, needed)) {
      *error = fmt::format("the GL context ({}) lacks {}", description, needed);
      return nullptr;
    }
  }
  return std::make_unique<MesaArbExecutor>(std::move(context), gl, description, limits);
}

}  // namespace arbiter::runtime
