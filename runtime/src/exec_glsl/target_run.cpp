// The target engines: see target_run.h. The points are one vertex buffer (every attribute a
// vec4 at its location, the binding map's ARB aliasing locations) drawn with glDrawArrays;
// no fixed-function state exists on these contexts: every GL state value reaches the shaders
// as a uniform.
#include "exec_glsl/target_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <limits>
#include <set>
#include <sstream>

#include "arbiter/runtime/mesa.h"
#include "arbiter/runtime/translate.h"
#include "exec/context.h"
#include "exec/draw.h"
#include "exec/exec_gl.h"
#include "exec/framebuffer.h"
#include "exec/program_cache.h"
#include "exec/textures.h"
#include "exec_glsl/glsl_program.h"
#include "exec_glsl/glsl_run.h"
#include "exec_glsl/target_adapt.h"
#include "vulkan/engine.h"

namespace arbiter::runtime {
namespace {

using exec::ExecGl;

constexpr int kLocations = 16;  // GL_MAX_VERTEX_ATTRIBS of Mesa's drivers
constexpr size_t kVertexFloats = static_cast<size_t>(kLocations) * 4;

std::string GetString(const ExecGl& gl, GLenum name) {
  const GLubyte* raw = gl.GetString(name);
  return raw != nullptr ? reinterpret_cast<const char*>(raw) : "";
}

bool HasExtension(const std::string& extensions, const std::string& name) {
  std::istringstream words(extensions);
  for (std::string word; words >> word;) {
    if (word == name) return true;
  }
  return false;
}

// The point's clip position goes to the highest location no attribute of the map holds
// (its ARB aliasing locations: vertex.normal is 2 here, where the ARB engine's plan only
// avoids the generic attributes), or to a uniform when all sixteen are taken.
void PlacePixel(const arbvp::BindingMap& map, exec::RunPlan* plan) {
  std::array<bool, kLocations> taken{};
  for (const arbvp::AttributeBinding& a : map.attributes) {
    if (a.location >= 0 && a.location < kLocations) taken[static_cast<size_t>(a.location)] = true;
  }
  plan->position_attrib = -1;
  for (int l = kLocations - 1; l > 0 && plan->position_attrib < 0; --l) {
    if (!taken[static_cast<size_t>(l)]) plan->position_attrib = l;
  }
}

class MesaTargetEngine final : public TargetEngine {
 public:
  MesaTargetEngine(std::unique_ptr<exec::GlContext> context, const ExecGl& gl,
                   arbvp::EmitTarget target, std::string description, int max_draw_buffers)
      : context_(std::move(context)),
        gl_(gl),
        dialect_(exec::DialectOf(target)),
        description_(std::move(description)),
        max_draw_buffers_(max_draw_buffers) {}

  const std::string& description() const override { return description_; }

  bool Run(const ArbPrograms& programs, const arbvp::EmitOptions& emit,
           const arbvp::ExecInputs& inputs, std::vector<arbvp::VectorResult>* results,
           std::string* not_applicable, std::string* error,
           const compiler::SourceFile* vertex_source,
           const compiler::SourceFile* fragment_source) override {
    results->clear();
    CheckedTranslation translation;
    if (!exec::TranslateForTarget(programs, emit, dialect_.target, vertex_source, fragment_source,
                                  &translation, not_applicable, error)) {
      return false;
    }
    exec::RunPlan plan;
    exec::ContextLimits limits;
    limits.max_draw_buffers = max_draw_buffers_;
    if (!exec::PlanRun(programs, limits, &plan, error)) return false;
    if (plan.mode != exec::RunMode::Fragment) PlacePixel(translation.bindings, &plan);
    std::vector<exec::GlslPass> passes;
    if (!exec::PlanTargetPasses(plan, translation, dialect_, std::min(max_draw_buffers_, 8),
                                &passes, error)) {
      return false;
    }
    if (!context_->MakeCurrent()) {
      *error = "cannot make the GL context current";
      return false;
    }
    for (int i = 0; i < 16 && gl_.GetError() != GL_NO_ERROR; ++i) {
    }
    const bool ok = RunPasses(plan, passes, translation.bindings, inputs, results, error);
    context_->Release();
    if (!ok) results->clear();
    return ok;
  }

 private:
  bool Check(const char* step, std::string* error) const { return exec::CheckGl(gl_, step, error); }

  // One vertex per vector: every attribute location the pass reads.
  std::vector<float> Vertices(const exec::RunPlan& plan, const arbvp::BindingMap& map,
                              const arbvp::ExecInputs& inputs, int width, int height,
                              std::array<bool, kLocations>* used, std::string* error) const {
    std::vector<float> data(inputs.vectors.size() * kVertexFloats, 0.0f);
    used->fill(false);
    auto put = [&](size_t i, int location, const arbvp::Vec4& v) {
      std::copy(v.begin(), v.end(),
                data.begin() + static_cast<ptrdiff_t>(i * kVertexFloats + 4 * location));
      (*used)[static_cast<size_t>(location)] = true;
    };
    for (size_t i = 0; i < inputs.vectors.size(); ++i) {
      const arbvp::InputVector& v = inputs.vectors[i];
      const arbvp::Vec4 clip =
          exec::PixelClipPosition(i, width, height, v.fragment.depth, inputs.state);
      auto put_point = [&](int location, const arbvp::Vec4& value) { put(i, location, value); };
      if (!exec::PointAttributes(plan, map, v, clip, put_point, error)) return {};
    }
    return data;
  }

  bool Draw(const exec::RunPlan& plan, const arbvp::BindingMap& map,
            const arbvp::ExecInputs& inputs, GLuint program, int width, int height,
            std::string* error) {
    std::array<bool, kLocations> used{};
    const std::vector<float> data = Vertices(plan, map, inputs, width, height, &used, error);
    if (!error->empty()) return false;
    gl_.BindBuffer(GL_ARRAY_BUFFER, buffer_);
    gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)),
                   data.data(), GL_STREAM_DRAW);
    for (int l = 0; l < kLocations; ++l) {
      const auto location = static_cast<GLuint>(l);
      if (!used[static_cast<size_t>(l)]) {
        gl_.DisableVertexAttribArray(location);
        continue;
      }
      gl_.EnableVertexAttribArray(location);
      gl_.VertexAttribPointer(location, 4, GL_FLOAT, GL_FALSE,
                              static_cast<GLsizei>(kVertexFloats * sizeof(float)),
                              reinterpret_cast<const void*>(static_cast<uintptr_t>(l) * 16));
    }
    const auto count = static_cast<GLsizei>(inputs.vectors.size());
    const GLint pixel = plan.mode != exec::RunMode::Fragment && plan.position_attrib < 0
                            ? gl_.GetUniformLocation(program, exec::kPixelAttribute)
                            : -1;
    if (pixel < 0) {
      gl_.DrawArrays(GL_POINTS, 0, count);
    } else {
      // Without a spare attribute location the position is a uniform, set point by point.
      for (GLsizei i = 0; i < count; ++i) {
        const arbvp::InputVector& v = inputs.vectors[static_cast<size_t>(i)];
        const arbvp::Vec4 clip = exec::PixelClipPosition(static_cast<size_t>(i), width, height,
                                                         v.fragment.depth, inputs.state);
        gl_.Uniform4fv(pixel, 1, clip.data());
        gl_.DrawArrays(GL_POINTS, i, 1);
      }
    }
    gl_.BindBuffer(GL_ARRAY_BUFFER, 0);
    return Check("drawing the points", error);
  }

  bool RunPasses(const exec::RunPlan& plan, const std::vector<exec::GlslPass>& passes,
                 const arbvp::BindingMap& map, const arbvp::ExecInputs& inputs,
                 std::vector<arbvp::VectorResult>* results, std::string* error) {
    const size_t count = inputs.vectors.size();
    results->assign(count, arbvp::VectorResult{});
    if (count == 0 || passes.empty()) return true;
    const int width = arbvp::kFramebufferWidth;
    const int height = arbvp::FramebufferHeight(count);
    size_t attachments = 1;
    for (const exec::GlslPass& pass : passes) {
      attachments = std::max(attachments, pass.attachments.size());
    }
    if (buffer_ == 0) {
      gl_.GenBuffers(1, &buffer_);
      // A core profile draws only with a vertex array object bound; ES has a default one.
      if (dialect_.target == arbvp::EmitTarget::Glsl330) {
        gl_.GenVertexArrays(1, &vertex_array_);
        gl_.BindVertexArray(vertex_array_);
      }
      if (dialect_.target == arbvp::EmitTarget::Glsl330) gl_.Enable(GL_PROGRAM_POINT_SIZE);
    }
    gl_.DepthRangef(inputs.state.depth_near, inputs.state.depth_far);
    if (!Check("setting up the context", error)) return false;
    std::vector<GLuint> textures;
    std::set<int> as_2d;  // the 1D and rectangle textures the translation emulates
    for (const arbvp::SamplerBinding& s : map.samplers) {
      if (arbvp::UploadsAs2D(s)) as_2d.insert(s.unit);
    }
    bool ok = exec::UploadTextures(gl_, inputs.textures, &textures, error,
                                   /*compatibility=*/false, as_2d) &&
              Check("creating the textures", error);
    if (ok) {
      exec::Framebuffer framebuffer(gl_);
      ok = framebuffer.Create(width, height, static_cast<int>(attachments), error) &&
           Check("creating the framebuffer", error);
      std::vector<std::vector<float>> values(plan.outputs.size());
      std::vector<float> alive;
      for (size_t p = 0; ok && p < passes.size(); ++p) {
        const exec::GlslPass& pass = passes[p];
        const GLuint program = exec::LinkCached(gl_, pass, map, plan, &programs_, error);
        ok = program != 0;
        if (!ok) break;
        gl_.UseProgram(program);
        ok = exec::SetTargetUniforms(gl_, program, map, inputs, height, error);
        // ES 1.00's readback rebuilds non-finite values from this uniform (target_adapt.cpp).
        const GLint special = gl_.GetUniformLocation(program, "arbiter_special");
        if (special >= 0) {
          const float special_values[4] = {std::numeric_limits<float>::infinity(),
                                           -std::numeric_limits<float>::infinity(),
                                           std::numeric_limits<float>::quiet_NaN(), 0.0f};
          gl_.Uniform4fv(special, 1, special_values);
        }
        ok = ok && Check("setting the uniforms", error);
        if (ok) {
          framebuffer.Begin(static_cast<int>(pass.attachments.size()));
          ok = Draw(plan, map, inputs, program, width, height, error);
        }
        for (size_t a = 0; ok && a < pass.attachments.size(); ++a) {
          const int slot = pass.attachments[a];
          if (slot == exec::kAliveFlag && !alive.empty()) continue;  // one pass says it
          framebuffer.Read(static_cast<int>(a),
                           slot == exec::kAliveFlag ? &alive : &values[static_cast<size_t>(slot)]);
          ok = Check("reading the framebuffer back", error);
        }
        gl_.UseProgram(0);
      }
      if (ok) exec::CollectResults(plan, values, alive, exec::GlslComponents, results);
    }
    exec::DeleteTextures(gl_, &textures);
    return ok && Check("cleaning up", error);
  }

  std::unique_ptr<exec::GlContext> context_;
  ExecGl gl_;
  exec::TargetDialect dialect_;
  std::string description_;
  int max_draw_buffers_ = 8;
  exec::ProgramCache programs_{8};
  GLuint buffer_ = 0;
  GLuint vertex_array_ = 0;
};

}  // namespace

std::unique_ptr<TargetEngine> CreateTargetEngine(arbvp::EmitTarget target,
                                                 const std::string& driver, std::string* error) {
  // vulkan-spirv: lavapipe whatever `driver` says (Mesa's one Vulkan driver without a GPU).
  if (target == arbvp::EmitTarget::Vk450) return vulkan::CreateVulkanEngine(error);
  exec::EglApi api = exec::EglApi::Core33;
  if (target == arbvp::EmitTarget::Es300) {
    api = exec::EglApi::Es3;
  } else if (target == arbvp::EmitTarget::Es100) {
    api = exec::EglApi::Es2;
  } else if (target != arbvp::EmitTarget::Glsl330) {
    *error = fmt::format("no Mesa engine runs the {} translation", arbvp::EmitTargetName(target));
    return nullptr;
  }
  if (!IsSupportedMesaDriver(driver)) {
    *error = fmt::format("unsupported Mesa driver '{}' (softpipe or llvmpipe)", driver);
    return nullptr;
  }
  exec::SetMesaEnvironment(driver);
  std::unique_ptr<exec::GlContext> context = exec::CreateEglApiContext(api, error);
  ExecGl gl;
  if (context == nullptr || !exec::MakeCurrentAndLoad(context.get(), "EGL", &gl, error)) {
    return nullptr;
  }
  const std::string renderer = GetString(gl, GL_RENDERER);
  const std::string description = fmt::format("{}, {} (egl)", renderer, GetString(gl, GL_VERSION));
  GLint max_draw_buffers = 1;
  gl.GetIntegerv(GL_MAX_DRAW_BUFFERS, &max_draw_buffers);
  std::vector<const char*> needed;
  // RGBA32F attachments and linear filtering of RGBA32F textures are extensions in ES, and
  // so are several attachments written from ES 1.00 shaders.
  if (target == arbvp::EmitTarget::Es300 || target == arbvp::EmitTarget::Es100) {
    needed = {"GL_EXT_color_buffer_float", "GL_OES_texture_float_linear"};
  }
  if (target == arbvp::EmitTarget::Es100) needed.push_back("GL_EXT_draw_buffers");
  const std::string extensions = needed.empty() ? "" : GetString(gl, GL_EXTENSIONS);
  for (int i = 0; i < 16 && gl.GetError() != GL_NO_ERROR; ++i) {
  }
  context->Release();
  if (renderer.rfind(driver, 0) != 0) {
    *error = fmt::format("egl runs '{}' in this process, not '{}'", renderer, driver);
    return nullptr;
  }
  for (const char* name : needed) {
    if (!HasExtension(extensions, name)) {
      *error = fmt::format("the GL context ({}) lacks {}", description, name);
      return nullptr;
    }
  }
  return std::make_unique<MesaTargetEngine>(std::move(context), gl, target, description,
                                            std::max(1, max_draw_buffers));
}

}  // namespace arbiter::runtime
