// The mesa-glsl engine: see glsl_run.h. The same GL state, textures, points and framebuffer
// as the ARB engine (executor.cpp), with GLSL program objects instead of ARB programs.
#include "exec_glsl/glsl_run.h"

#include <fmt/format.h>

#include <algorithm>

#include "arbiter/runtime/translate.h"
#include "exec/draw.h"
#include "exec/framebuffer.h"
#include "exec/state_upload.h"
#include "exec/textures.h"
#include "exec_glsl/glsl_adapt.h"
#include "exec_glsl/glsl_program.h"

namespace arbiter::runtime::exec {
namespace {

// As the ARB engine's SetFixedState, with the ARB program targets off (a current GLSL
// program wins anyway) and the same colour clamping: on for a pair, off otherwise.
void SetFixedState(const ExecGl& gl, RunMode mode) {
  gl.ClampColorARB(GL_CLAMP_VERTEX_COLOR_ARB, mode == RunMode::Pair ? GL_TRUE : GL_FALSE);
  gl.ClampColorARB(GL_CLAMP_FRAGMENT_COLOR_ARB, GL_FALSE);
  gl.ClampColorARB(GL_CLAMP_READ_COLOR_ARB, GL_FALSE);
  gl.Disable(GL_VERTEX_PROGRAM_ARB);
  gl.Disable(GL_FRAGMENT_PROGRAM_ARB);
  gl.Enable(GL_VERTEX_PROGRAM_POINT_SIZE);  // gl_PointSize (the ARB enum's value)
  for (GLenum cap : {GL_DEPTH_TEST, GL_BLEND, GL_POINT_SMOOTH, GL_POINT_SPRITE_ARB, GL_CULL_FACE,
                     GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_FOG}) {
    gl.Disable(cap);
  }
}

// The translation of `programs` with glslang's verdict, the cached one for the same text.
CheckedTranslation Translate(const ArbPrograms& programs, const arbvp::EmitOptions& emit,
                             GlslCache* cache) {
  CheckedTranslation t =
      EmitTranslation(programs.vertex, programs.fragment, emit, nullptr, nullptr);
  if (!t.error.empty()) return t;
  if (cache->checked && cache->vertex == t.vertex && cache->fragment == t.fragment) {
    t.ok = cache->ok;
    t.error = cache->error;
    return t;
  }
  SelfCheckTranslation(&t);
  cache->checked = true;
  cache->vertex = t.vertex;
  cache->fragment = t.fragment;
  cache->ok = t.ok;
  cache->error = t.error;
  return t;
}

struct Run {
  const ExecGl& gl;
  const RunPlan& plan;
  const CheckedTranslation& translation;
  const ArbPrograms& programs;
  const arbvp::ExecInputs& inputs;
  ProgramCache* cache;

  bool Pass(const GlslPass& pass, int width, int height, Framebuffer* framebuffer,
            std::vector<std::vector<float>>* values, std::vector<float>* alive,
            std::string* error) const {
    const GLuint program = LinkCached(gl, pass, translation.bindings, plan, cache, error);
    if (program == 0) return false;
    gl.UseProgram(program);
    bool ok = SetGlslUniforms(gl, program, translation.bindings, programs, inputs, error) &&
              CheckGl(gl, "setting the uniforms", error);
    if (ok) {
      framebuffer->Begin(static_cast<int>(pass.attachments.size()));
      // Without a spare generic attribute the position is a uniform, set point by point.
      const GLint pixel = plan.mode != RunMode::Fragment && plan.position_attrib < 0
                              ? gl.GetUniformLocation(program, kPixelAttribute)
                              : -1;
      DrawPoints(gl, plan, inputs, width, height, pixel);
      ok = CheckGl(gl, "drawing the points", error);
    }
    for (size_t a = 0; ok && a < pass.attachments.size(); ++a) {
      const int slot = pass.attachments[a];
      if (slot == kAliveFlag && !alive->empty()) continue;  // one pass says it
      framebuffer->Read(static_cast<int>(a),
                        slot == kAliveFlag ? alive : &(*values)[static_cast<size_t>(slot)]);
      ok = CheckGl(gl, "reading the framebuffer back", error);
    }
    gl.UseProgram(0);
    return ok;
  }
};

}  // namespace

bool CheckGl(const ExecGl& gl, const char* step, std::string* error) {
  const GLenum code = gl.GetError();
  if (code == GL_NO_ERROR) return true;
  *error = fmt::format("{} raised {}", step, GlErrorName(code));
  return false;
}

uint8_t GlslComponents(const arbvp::Binding& b) {
  switch (b.result) {
    case arbvp::ResultReg::FogCoord:
    case arbvp::ResultReg::PointSize:
      return 0x1;
    case arbvp::ResultReg::FragDepth:
      return 0x4;
    default:
      return 0xF;
  }
}

// What decides a linked program: both texts and the attribute locations bound before
// linking (LinkGlslPass).
GLuint LinkCached(const ExecGl& gl, const GlslPass& pass, const arbvp::BindingMap& map,
                  const RunPlan& plan, ProgramCache* cache, std::string* error) {
  std::string key = pass.vertex + '\0' + pass.fragment + '\0';
  key += fmt::format("{} {}", static_cast<int>(plan.mode), plan.position_attrib);
  for (const arbvp::AttributeBinding& a : map.attributes) {
    key += fmt::format(" {}={}", a.name, a.location);
  }
  GLuint program = cache->Find(key);
  if (program != 0) return program;
  program = LinkGlslPass(gl, pass, map, plan, error);
  if (program == 0) return 0;
  const GLuint evicted = cache->Add(std::move(key), program);
  if (evicted != 0) gl.DeleteProgram(evicted);
  return program;
}

bool RunGlslTranslation(const ExecGl& gl, const ContextLimits& limits, const ArbPrograms& programs,
                        const arbvp::EmitOptions& emit, const arbvp::ExecInputs& inputs,
                        GlslCache* cache, std::vector<arbvp::VectorResult>* results,
                        std::string* error) {
  results->clear();
  RunPlan plan;
  if (!PlanRun(programs, limits, &plan, error)) return false;
  const CheckedTranslation translation = Translate(programs, emit, cache);
  if (!translation.ok) {
    *error = "the translation failed its self-check: " + translation.error;
    return false;
  }
  const int max_attachments = std::min(limits.max_draw_buffers, 8);
  std::vector<GlslPass> passes;
  if (!PlanGlslPasses(plan, translation, max_attachments, &passes, error)) return false;

  const size_t count = inputs.vectors.size();
  results->assign(count, arbvp::VectorResult{});
  if (count == 0 || passes.empty()) return true;
  const int width = arbvp::kFramebufferWidth;
  const int height =
      static_cast<int>((count + static_cast<size_t>(width) - 1) / static_cast<size_t>(width));
  size_t attachments = 1;
  for (const GlslPass& pass : passes) attachments = std::max(attachments, pass.attachments.size());

  SetFixedState(gl, plan.mode);
  UploadGlState(gl, inputs.state);
  if (!CheckGl(gl, "setting the GL state", error)) return false;
  std::vector<GLuint> textures;
  bool ok = UploadTextures(gl, inputs.textures, &textures, error) &&
            CheckGl(gl, "creating the textures", error);
  if (ok) {
    Framebuffer framebuffer(gl);
    ok = framebuffer.Create(width, height, static_cast<int>(attachments), error) &&
         CheckGl(gl, "creating the framebuffer", error);
    std::vector<std::vector<float>> values(plan.outputs.size());
    std::vector<float> alive;
    const Run run{gl, plan, translation, programs, inputs, &cache->programs};
    for (size_t p = 0; ok && p < passes.size(); ++p) {
      ok = run.Pass(passes[p], width, height, &framebuffer, &values, &alive, error);
    }
    if (ok) CollectResults(plan, values, alive, GlslComponents, results);
  }
  DeleteTextures(gl, &textures);
  ok = ok && CheckGl(gl, "cleaning up", error);
  if (!ok) results->clear();
  return ok;
}

}  // namespace arbiter::runtime::exec
