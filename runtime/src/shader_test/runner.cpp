// RunShaderTests: tests go to worker processes in small chunks, -j at a time; each worker
// creates one GL context and runs its chunk on it. A chunk whose worker crashes, hangs or
// runs out of memory is run again one test per worker, so that only the guilty test fails.
#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "arbiter/compiler/source.h"
#include "arbiter/runtime/mesa.h"
#include "arbiter/runtime/shader_test.h"
#include "exec/context.h"
#include "shader_test/session.h"
#include "worker/chunks.h"

namespace arbiter::runtime {
namespace {

using shader_test::ContextInfo;
using shader_test::Session;
using shader_test::Window;

// A worker's GL context and the window framebuffer it reuses while the size stays.
class Runner {
 public:
  bool Create(const RunOptions& options, std::string* error) {
    if (!IsSupportedMesaDriver(options.exec.driver)) {
      *error =
          fmt::format("unsupported Mesa driver '{}' (softpipe or llvmpipe)", options.exec.driver);
      return false;
    }
    exec::SetMesaEnvironment(options.exec.driver);
    context_ = options.exec.backend == Backend::Egl ? exec::CreateEglContext(error)
                                                    : exec::CreateOsMesaContext(error);
    if (context_ == nullptr) return false;
    if (!context_->MakeCurrent()) {
      *error = fmt::format("cannot make the {} context current", BackendName(options.exec.backend));
      return false;
    }
    if (!exec::LoadExecGl(context_->get_proc(), &gl_, error)) return false;
    auto text = [&](GLenum name) {
      const GLubyte* s = gl_.GetString(name);
      return s != nullptr ? std::string(reinterpret_cast<const char*>(s)) : std::string();
    };
    info_.renderer = text(GL_RENDERER);
    info_.gl_version = std::strtod(text(GL_VERSION).c_str(), nullptr);
    info_.glsl_version = std::strtod(text(GL_SHADING_LANGUAGE_VERSION).c_str(), nullptr);
    std::istringstream words(text(GL_EXTENSIONS));
    for (std::string word; words >> word;) info_.extensions.insert(word);
    if (info_.renderer.rfind(options.exec.driver, 0) != 0) {
      *error = fmt::format("{} runs '{}', not '{}'", BackendName(options.exec.backend),
                           info_.renderer, options.exec.driver);
      return false;
    }
    return true;
  }

  // Makes (or keeps) the window framebuffer of the given size.
  bool Resize(int width, int height, std::string* error) {
    if (window_.framebuffer != 0 && window_.width == width && window_.height == height) {
      return true;
    }
    if (window_.framebuffer != 0) {
      gl_.DeleteFramebuffers(1, &window_.framebuffer);
      gl_.DeleteRenderbuffers(2, window_.renderbuffers.data());
    }
    window_.width = width;
    window_.height = height;
    gl_.GenFramebuffers(1, &window_.framebuffer);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, window_.framebuffer);
    gl_.GenRenderbuffers(2, window_.renderbuffers.data());
    gl_.BindRenderbuffer(GL_RENDERBUFFER, window_.renderbuffers[0]);
    gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                window_.renderbuffers[0]);
    gl_.BindRenderbuffer(GL_RENDERBUFFER, window_.renderbuffers[1]);
    gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                window_.renderbuffers[1]);
    gl_.BindRenderbuffer(GL_RENDERBUFFER, 0);
    const GLenum status = gl_.CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      *error = fmt::format("the {}x{} RGBA8 window framebuffer is incomplete (0x{:04x})", width,
                           height, status);
      window_.framebuffer = 0;
      return false;
    }
    const GLenum buffer = GL_COLOR_ATTACHMENT0;
    gl_.DrawBuffers(1, &buffer);
    gl_.ReadBuffer(GL_COLOR_ATTACHMENT0);
    return true;
  }

  ShaderTestResult Run(const std::string& path, const std::string& png, const RunOptions& options) {
    ShaderTestResult result;
    result.path = path;
    std::string bytes;
    std::string error;
    ShaderTest test;
    int width = 0, height = 0;
    if (!compiler::ReadFileBytes(path, &bytes, &error)) {
      result.message = fmt::format("{}: cannot read the test: {}", path, error);
      return result;
    }
    int error_line = 0;
    if (!ParseShaderTest(bytes, path, &test, &error_line, &error)) {
      result.message = fmt::format("{}:{}: {}", path, error_line, error);
      return result;
    }
    if (!Session::WindowSize(test, &width, &height, &error)) {
      result.message = error;
      return result;
    }
    if (!Resize(width, height, &error)) {
      result.message = fmt::format("{}: {}", path, error);
      return result;
    }
    std::vector<uint8_t> image;
    Session session(gl_, info_, &window_, options, test, &result);
    session.Run(png.empty() ? nullptr : &image);
    if (!png.empty() && result.status != TestStatus::Skip) {
      std::filesystem::create_directories(std::filesystem::path(png).parent_path(), ec_);
      if (!WritePng(png, width, height, image, &error)) {
        result.status = TestStatus::Fail;
        result.message +=
            fmt::format("{}cannot write {}: {}", result.message.empty() ? "" : "\n", png, error);
      } else {
        result.png = png;
      }
    }
    return result;
  }

 private:
  std::unique_ptr<exec::GlContext> context_;
  exec::ExecGl gl_;
  ContextInfo info_;
  Window window_;
  std::error_code ec_;
};

nlohmann::json ToJson(const ShaderTestResult& r) {
  return {{"status", static_cast<int>(r.status)},
          {"message", r.message},
          {"diagnostics", r.diagnostics},
          {"warnings", r.warnings},
          {"png", r.png},
          {"environment", r.environment}};
}

ShaderTestResult FromJson(const std::string& path, const nlohmann::json& j) {
  ShaderTestResult r;
  r.path = path;
  r.status = static_cast<TestStatus>(j.value("status", 1));
  r.message = j.value("message", "");
  r.diagnostics = j.value("diagnostics", std::vector<std::string>{});
  r.warnings = j.value("warnings", std::vector<std::string>{});
  r.png = j.value("png", "");
  r.environment = j.value("environment", false);
  return r;
}

// The job that runs tests [first, first + count) on one GL context; its payload is a JSON array of
// results.
WorkerJob ChunkJob(const std::vector<std::string>& paths, size_t first, size_t count,
                   const RunOptions& options) {
  return [&paths, first, count, &options](std::string* payload, std::string* job_error) {
    auto runner = std::make_unique<Runner>();
    if (!runner->Create(options, job_error)) return false;
    nlohmann::json out = nlohmann::json::array();
    for (size_t i = first; i < first + count; ++i) {
      const std::string png = options.png_dir.empty() || i >= options.png_names.size()
                                  ? ""
                                  : options.png_dir + "/" + options.png_names[i];
      out.push_back(ToJson(runner->Run(paths[i], png, options)));
    }
    *payload = out.dump();
    // The worker exits right after its job: the system frees the context faster than
    // destroying it does.
    (void)runner.release();
    return true;
  };
}

}  // namespace

std::vector<ShaderTestResult> RunShaderTests(const std::vector<std::string>& paths,
                                             const RunOptions& options) {
  std::vector<ShaderTestResult> results(paths.size());
  if (paths.empty()) return results;
  if (options.exec.backend == Backend::OSMesa) exec::PreloadOsMesa();
  ChunkedBatch batch;
  batch.items = paths.size();
  batch.workers = static_cast<size_t>(std::max(1, options.jobs));
  // Small chunks: a test's cost varies with its draws, so many chunks balance the workers.
  batch.per_worker = 4;
  batch.largest = 16;
  batch.limits = options.limits;
  batch.make_job = [&](size_t first, size_t count) {
    return ChunkJob(paths, first, count, options);
  };
  batch.read = [&](size_t i, const nlohmann::json& entry) {
    results[i] = FromJson(paths[i], entry);
    return true;
  };
  batch.failed = [&](size_t i, const std::string& error, bool environment) {
    ShaderTestResult& r = results[i];
    r = ShaderTestResult{};
    r.path = paths[i];
    r.message = fmt::format("{}: {}", paths[i], error);
    r.environment = environment;  // no GL context: not the test's fault
  };
  RunChunked(batch);
  return results;
}

}  // namespace arbiter::runtime
