// RunGlsl: one context (as the ARB executor makes it), the GL state and textures, the vertex
// and fragment runs, the notes on unset uniforms; and RunGlslInWorker, which carries the
// result out of a worker process as JSON.
#include <fmt/format.h>

#include <algorithm>

#include "arbiter/arbvp/exec_io.h"
#include "arbiter/runtime/glsl_exec.h"
#include "arbiter/runtime/mesa.h"
#include "exec/context.h"
#include "exec/state_upload.h"
#include "exec/textures.h"
#include "glsl_exec/run.h"
#include "glsl_exec/types.h"

namespace arbiter::runtime {
namespace {

using glsl_exec::ActiveUniform;

std::string GetString(const exec::ExecGl& gl, GLenum name) {
  const GLubyte* raw = gl.GetString(name);
  return raw != nullptr ? reinterpret_cast<const char*>(raw) : "";
}

void DrainErrors(const exec::ExecGl& gl) {
  for (int i = 0; i < 16 && gl.GetError() != GL_NO_ERROR; ++i) {
  }
}

}  // namespace

namespace glsl_exec {

void FinishUniformNotes(const GlslExecInputs& inputs, const std::vector<UniformSeen>& active,
                        const std::set<std::string>& used, const std::set<size_t>& applied,
                        std::string_view compiler, GlslRunResult* result) {
  for (const UniformSeen& u : active) {
    if (used.count(u.name) > 0) continue;
    std::string name = u.name;
    if (name.ends_with("[0]") && u.size > 1) name = name.substr(0, name.size() - 3);
    result->notes.push_back(u.sampler
                                ? fmt::format("sampler {} not set: reads texture unit 0", name)
                                : fmt::format("uniform {} not set: read as zero", name));
  }
  for (size_t a = 0; a < inputs.uniforms.size(); ++a) {
    if (applied.count(a) > 0) continue;
    const std::string& name = inputs.uniforms[a].first;
    const std::string base = name.substr(0, std::min(name.find('['), name.find('.')));
    const std::vector<std::string>& declared = inputs.declared_uniforms;
    if (std::find(declared.begin(), declared.end(), base) == declared.end()) {
      // A --uniform that names nothing the shaders declare is a usage error, not a note.
      std::vector<std::string> names;
      names.reserve(active.size());
      for (const UniformSeen& u : active) names.push_back(u.name);
      result->usage_error =
          fmt::format("--uniform {}: the shaders have no uniform '{}'{}", name, name,
                      names.empty() ? std::string()
                                    : fmt::format("; active uniforms: {}", fmt::join(names, ", ")));
      result->vectors.clear();
      result->notes.clear();
      return;
    }
    result->notes.push_back(fmt::format(
        "uniform {} is not active ({} removed it: the outputs do not depend on it): ignored", name,
        compiler));
  }
}

}  // namespace glsl_exec

bool RunGlsl(const ExecOptions& options, const GlslShaders& shaders, const GlslExecInputs& inputs,
             GlslRunResult* result, std::string* error) {
  *result = GlslRunResult{};
  if (!IsSupportedMesaDriver(options.driver)) {
    *error = fmt::format("unsupported Mesa driver '{}' (softpipe or llvmpipe)", options.driver);
    return false;
  }
  exec::SetMesaEnvironment(options.driver);
  std::unique_ptr<exec::GlContext> context = options.backend == Backend::Egl
                                                 ? exec::CreateEglContext(error)
                                                 : exec::CreateOsMesaContext(error);
  glsl_exec::Gl gl;
  if (context == nullptr ||
      !exec::MakeCurrentAndLoad(context.get(), std::string(BackendName(options.backend)), &gl,
                                error)) {
    return false;
  }
  if (!glsl_exec::LoadExtraGl(context->get_proc(), &gl, error)) {
    context->Release();
    return false;
  }
  const std::string renderer = GetString(gl, GL_RENDERER);
  result->description =
      fmt::format("{}, {} ({})", renderer, GetString(gl, GL_VERSION), BackendName(options.backend));
  if (renderer.rfind(options.driver, 0) != 0) {
    *error = fmt::format("{} runs '{}' in this process, not '{}'", BackendName(options.backend),
                         renderer, options.driver);
    context->Release();
    return false;
  }
  DrainErrors(gl);
  exec::UploadGlState(gl, inputs.state);
  std::vector<GLuint> textures;
  bool ok = exec::UploadTextures(gl, inputs.textures, &textures, error);
  std::set<std::string> used;
  std::set<size_t> applied;
  std::vector<ActiveUniform> active;
  const glsl_exec::RunContext run{
      gl, shaders, inputs, &used, &applied, &active, &result->usage_error};
  result->vectors.assign(inputs.vectors.size(), GlslVectorResult{});
  if (ok && !shaders.vertex.empty()) ok = glsl_exec::RunVertex(run, &result->vectors, error);
  if (ok && !shaders.fragment.empty()) ok = glsl_exec::RunFragment(run, &result->vectors, error);
  exec::DeleteTextures(gl, &textures);
  DrainErrors(gl);
  context->Release();
  if (!result->usage_error.empty()) {
    result->vectors.clear();
    return true;
  }
  if (!ok) return false;
  std::vector<glsl_exec::UniformSeen> seen;
  for (const ActiveUniform& u : active) {
    seen.push_back(
        {u.name, u.size, glsl_exec::LookUpGlType(u.type).base == glsl_exec::BaseKind::Sampler});
  }
  glsl_exec::FinishUniformNotes(inputs, seen, used, applied, "Mesa", result);
  return true;
}

nlohmann::ordered_json GlslResultsToJson(const std::vector<GlslVectorResult>& results) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const GlslVectorResult& r : results) {
    nlohmann::ordered_json outputs = nlohmann::ordered_json::array();
    for (const GlslOutput& o : r.outputs) {
      nlohmann::ordered_json value = nlohmann::ordered_json::array();
      for (float f : o.value) value.push_back(arbvp::FloatToJson(f));
      outputs.push_back(
          {{"name", o.name}, {"stage", o.stage}, {"type", o.type}, {"value", std::move(value)}});
    }
    list.push_back({{"discarded", r.discarded}, {"outputs", std::move(outputs)}});
  }
  return list;
}

namespace {

float FloatFromJson(const nlohmann::json& v) {
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    if (s == "nan") return std::numeric_limits<float>::quiet_NaN();
    return s == "-inf" ? -std::numeric_limits<float>::infinity()
                       : std::numeric_limits<float>::infinity();
  }
  return v.get<float>();
}

}  // namespace

nlohmann::ordered_json GlslRunResultToJson(const GlslRunResult& result) {
  return {{"description", result.description},
          {"usage_error", result.usage_error},
          {"notes", result.notes},
          {"vectors", GlslResultsToJson(result.vectors)}};
}

bool GlslRunResultFromJson(const nlohmann::json& j, GlslRunResult* result) {
  *result = GlslRunResult{};
  try {
    result->description = j.at("description").get<std::string>();
    result->usage_error = j.at("usage_error").get<std::string>();
    result->notes = j.at("notes").get<std::vector<std::string>>();
    for (const nlohmann::json& jv : j.at("vectors")) {
      GlslVectorResult r;
      r.discarded = jv.at("discarded").get<bool>();
      for (const nlohmann::json& jo : jv.at("outputs")) {
        GlslOutput o{jo.at("name").get<std::string>(),
                     jo.at("stage").get<std::string>(),
                     jo.at("type").get<std::string>(),
                     {}};
        for (const nlohmann::json& f : jo.at("value")) o.value.push_back(FloatFromJson(f));
        r.outputs.push_back(std::move(o));
      }
      result->vectors.push_back(std::move(r));
    }
  } catch (const nlohmann::json::exception&) {
    return false;
  }
  return true;
}

WorkerStatus RunGlslInWorker(const ExecOptions& options, const WorkerLimits& limits,
                             const GlslShaders& shaders, const GlslExecInputs& inputs,
                             GlslRunResult* result, std::string* error) {
  auto job = [&](std::string* payload, std::string* job_error) {
    GlslRunResult out;
    if (!RunGlsl(options, shaders, inputs, &out, job_error)) return false;
    *payload = GlslRunResultToJson(out).dump();
    return true;
  };
  std::string payload;
  const WorkerStatus status = RunInWorker(limits, job, &payload, error);
  if (status != WorkerStatus::Ok) return status;
  const nlohmann::json j = nlohmann::json::parse(payload, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !GlslRunResultFromJson(j, result)) {
    *error = "the worker's answer is not a run's result";
    return WorkerStatus::Crashed;
  }
  return WorkerStatus::Ok;
}

}  // namespace arbiter::runtime
