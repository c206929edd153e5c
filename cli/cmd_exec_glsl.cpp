// arbiter exec for GLSL shaders: check the shaders with arbiter's own GLSL checker, build the
// inputs from --set/--uniform/--state/--texture/--vectors, run them on Mesa in a worker, and
// print every output per vector (exec_glsl.h).
#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "arbiter/arbvp/exec_io.h"
#include "arbiter/glsl/link.h"
#include "arbiter/glsl/reflect.h"
#include "arbiter/runtime/glsl_exec.h"
#include "arbiter/runtime/glsl_vulkan.h"
#include "arbiter/runtime/mesa.h"
#include "arbiter/runtime/worker.h"
#include "exec_glsl.h"
#include "load_arb.h"

namespace arbiter::cli {
namespace {

Exit Fail(std::string_view message, Exit exit) {
  fmt::print(stderr, "arbiter: error: {}\n", message);
  return exit;
}

// The shaders read and checked; diagnostics in `reports` (one per file).
struct Loaded {
  std::vector<std::unique_ptr<compiler::SourceFile>> keep;  // vertex first
  const compiler::SourceFile* vertex = nullptr;
  const compiler::SourceFile* fragment = nullptr;
  glsl::Reflection vertex_reflection;
  glsl::Reflection fragment_reflection;
  std::vector<compiler::FileReport> reports;
  std::vector<std::string> files;
};

Exit LoadShaders(const ExecGlslOptions& options, Loaded* out) {
  const CommonOptions& common = *options.common;
  std::vector<Input> inputs;
  for (const std::string& file : common.files) {
    inputs.push_back({file, file == "-" ? "<stdin>" : file, {}, false, {}});
  }
  Exit exit = Exit::Ok;
  std::vector<std::unique_ptr<compiler::SourceFile>> sources;
  std::vector<glsl::Stage> stages;
  for (const Input& input : inputs) {
    std::optional<glsl::Stage> stage = GlslStage(common, input);
    if (!stage) {
      return Fail(fmt::format("cannot tell the GLSL stage of '{}': name it .vert or .frag (or "
                              ".vs .vsh .fs .fsh, .vert.glsl .frag.glsl), or give --stage "
                              "vert|frag",
                              input.display_path),
                  Exit::Usage);
    }
    compiler::FileReport report;
    report.path = input.display_path;
    std::unique_ptr<compiler::SourceFile> source = ReadInput(input, &report);
    if (!source) exit = Exit::Environment;
    out->reports.push_back(std::move(report));
    out->files.push_back(input.display_path);
    sources.push_back(std::move(source));
    stages.push_back(*stage);
  }
  if (sources.size() > 2 || (sources.size() == 2 && stages[0] == stages[1])) {
    return Fail("exec runs one GLSL shader, or one vertex shader and one fragment shader as a pair",
                Exit::Usage);
  }
  if (options.pair && sources.size() != 2) {
    return Fail("--pair needs a vertex shader and a fragment shader", Exit::Usage);
  }
  if (exit != Exit::Ok) return exit;
  std::vector<std::unique_ptr<compiler::SourceFile>> ordered(sources.size());
  for (size_t i = 0; i < sources.size(); ++i) {
    if (stages[i] == glsl::Stage::Vertex) {
      out->vertex = sources[i].get();
    } else {
      out->fragment = sources[i].get();
    }
  }
  GlslSetup setup;
  if (std::optional<Exit> failed = ResolveGlslSetup(common, &setup)) return *failed;
  compiler::DiagnosticSink sink(common.error_limit);
  bool ok = false;
  if (out->vertex != nullptr && out->fragment != nullptr) {
    glsl::LinkOptions link;
    link.check = setup.check;
    glsl::LinkResult result = glsl::LinkProgram({out->vertex}, {out->fragment}, link, &sink);
    ok = result.ok;
    out->vertex_reflection = std::move(result.vertex);
    out->fragment_reflection = std::move(result.fragment);
  } else if (out->vertex != nullptr) {
    out->vertex_reflection =
        glsl::ReflectShader(glsl::Stage::Vertex, {out->vertex}, &sink, setup.check);
    ok = out->vertex_reflection.ok;
  } else {
    out->fragment_reflection =
        glsl::ReflectShader(glsl::Stage::Fragment, {out->fragment}, &sink, setup.check);
    ok = out->fragment_reflection.ok;
  }
  sink.ApplyWarningPolicy(setup.warnings);
  out->keep = std::move(sources);
  DistributeDiagnostics(&sink, out->keep, &out->reports);
  return ok && sink.error_count() == 0 ? Exit::Ok : Exit::Rejected;
}

// A --uniform of a declared uniform of a plain type (not a structure) with the wrong number of
// values, judged from arbiter's reflection (Mesa's program judges the others, and cannot judge
// a uniform it removed as inactive).
std::optional<std::string> WrongUniformCount(const Loaded& loaded, const std::string& name,
                                             size_t count) {
  for (const glsl::Reflection* r : {&loaded.vertex_reflection, &loaded.fragment_reflection}) {
    for (const auto* list : {&r->uniforms, &r->samplers}) {
      for (const glsl::ReflectedVariable& v : *list) {
        if (v.type.starts_with("struct") || v.components == 0) continue;
        const size_t elements = static_cast<size_t>(std::max(v.array_size, 1));
        const size_t per = static_cast<size_t>(v.components) / elements;
        if (name == v.name && v.array_size == 0 && count != per) {
          return fmt::format("--uniform {}: {} is a {} and takes {} value(s), not {}", name, name,
                             v.type, per, count);
        }
        if (name == v.name && v.array_size > 0 &&
            (count % per != 0 || count == 0 || count > per * elements)) {
          return fmt::format(
              "--uniform {}: {} is a {}[{}] and takes {} value(s) per element, for 1 to {} "
              "elements, not {} value(s)",
              name, name, v.type, elements, per, elements, count);
        }
        if (name.starts_with(v.name + "[") && v.array_size > 0 && count != per) {
          return fmt::format("--uniform {}: {} is a {} and takes {} value(s), not {}", name, name,
                             v.type, per, count);
        }
      }
    }
  }
  return std::nullopt;
}

bool BuildInputs(const ExecGlslOptions& options, const Loaded& loaded,
                 runtime::GlslExecInputs* inputs, std::vector<std::string>* warnings) {
  inputs->slots = runtime::GlslInputSlots(loaded.vertex ? &loaded.vertex_reflection : nullptr,
                                          loaded.fragment ? &loaded.fragment_reflection : nullptr);
  for (const glsl::Reflection* r : {&loaded.vertex_reflection, &loaded.fragment_reflection}) {
    for (const auto* list : {&r->uniforms, &r->samplers}) {
      for (const glsl::ReflectedVariable& v : *list) inputs->declared_uniforms.push_back(v.name);
    }
  }
  std::string error;
  if (!options.vectors.empty()) {
    std::string text;
    if (!compiler::ReadFileBytes(options.vectors, &text, &error) ||
        !runtime::ParseGlslVectorsJson(text, inputs, &error)) {
      fmt::print(stderr, "arbiter: error: {}: {}\n", options.vectors, error);
      return false;
    }
  } else {
    std::map<std::string, std::vector<float>> base;
    for (const runtime::GlslInputSlot& slot : inputs->slots) base[slot.name] = slot.fill;
    inputs->vectors.push_back(std::move(base));
  }
  // GL state and textures: the ARB exec's names (state.*) and patterns.
  arbvp::ExecInputs arb;
  arb.state = inputs->state;
  arb.textures = inputs->textures;
  arb.vectors.emplace_back();
  for (const std::string& state : options.state) {
    if (!state.starts_with("state.")) {
      fmt::print(stderr, "arbiter: error: --state '{}': names start with 'state.'\n", state);
      return false;
    }
    if (!arbvp::ApplyAssignment(state, &arb, &arb.vectors.front(), &error)) {
      fmt::print(stderr, "arbiter: error: {}\n", error);
      return false;
    }
  }
  for (const std::string& flag : options.textures) {
    if (!arbvp::ApplyTextureFlag(flag, &arb, &error)) {
      fmt::print(stderr, "arbiter: error: --texture {}\n", error);
      return false;
    }
  }
  inputs->state = arb.state;
  inputs->textures = arb.textures;
  if (loaded.vertex_reflection.samplers.empty() && loaded.fragment_reflection.samplers.empty()) {
    for (const auto& [unit, texture] : inputs->textures) {
      warnings->push_back(fmt::format("--texture {}: the shaders sample no texture", unit));
    }
  }
  for (const std::string& assignment : options.set) {
    std::string name;
    std::vector<float> values;
    if (!runtime::ParseGlslSet(inputs->slots, assignment, &name, &values, &error)) {
      fmt::print(stderr, "arbiter: error: {}\n", error);
      return false;
    }
    for (auto& v : inputs->vectors) v[name] = values;
    for (const runtime::GlslInputSlot& slot : inputs->slots) {
      if (slot.name == name && !slot.read) {
        warnings->push_back(fmt::format("--set {}: the shader never reads {}", assignment, name));
      }
    }
  }
  for (const std::string& assignment : options.uniforms) {
    std::string name;
    std::vector<float> values;
    if (!runtime::ParseGlslUniform(assignment, &name, &values, &error)) {
      fmt::print(stderr, "arbiter: error: {}\n", error);
      return false;
    }
    if (std::optional<std::string> wrong = WrongUniformCount(loaded, name, values.size())) {
      fmt::print(stderr, "arbiter: error: {}\n", *wrong);
      return false;
    }
    inputs->uniforms.emplace_back(name, values);
  }
  return true;
}

// Text: one block per vector, one line per output (a matrix: one per column, m[0], m[1], ..),
// in the ARB exec's columns.
void PrintText(const runtime::GlslRunResult& result) {
  std::string out;
  for (size_t v = 0; v < result.vectors.size(); ++v) {
    const runtime::GlslVectorResult& r = result.vectors[v];
    out += fmt::format("vector {}\n", v);
    for (const runtime::GlslOutput& o : r.outputs) {
      const size_t size = o.value.size();
      size_t columns = 1;
      if (o.type.starts_with("mat")) columns = static_cast<size_t>(o.type[3] - '0');
      const size_t rows = size / columns;
      for (size_t c = 0; c < columns; ++c) {
        std::string name = columns > 1 ? fmt::format("{}[{}]", o.name, c) : o.name;
        std::string line = fmt::format("  {:<28}", name);
        for (size_t k = 0; k < rows; ++k) {
          line += fmt::format(" {:>14}", arbvp::FormatFloat(o.value[c * rows + k]));
        }
        out += line + "\n";
      }
    }
    if (r.discarded) out += fmt::format("  {:<28}discarded\n", "(fragment)");
  }
  fmt::print("{}", out);
}

void PrintJson(const Loaded& loaded, const runtime::GlslRunResult* result,
               const std::vector<std::string>& warnings, const char* engine = "mesa") {
  nlohmann::ordered_json j;
  j["files"] = loaded.files;
  j["language"] = "glsl";
  nlohmann::ordered_json engines = nlohmann::ordered_json::object();
  if (result != nullptr) engines[engine] = runtime::GlslResultsToJson(result->vectors);
  j["results"] = engines;
  j["notes"] = result != nullptr ? result->notes : std::vector<std::string>{};
  std::vector<compiler::FileReport> with_diagnostics;  // as the ARB exec: files that have any
  for (const compiler::FileReport& report : loaded.reports) {
    if (!report.diagnostics.empty() || report.dropped_errors > 0) {
      with_diagnostics.push_back(report);
    }
  }
  j["diagnostics"] = DiagnosticsJson(with_diagnostics);
  j["warnings"] = warnings;
  fmt::print("{}\n", j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
}

}  // namespace

bool ExecFilesAreGlsl(const CommonOptions& options) {
  for (const std::string& file : options.files) {
    const Input input{file, file, {}, false, {}};
    if (GlslStage(options, input) || glsl::IsGlslPath(file)) return true;
  }
  return false;
}

int RunExecGlsl(const ExecGlslOptions& options) {
  const CommonOptions& common = *options.common;
  // GLSL runs on Mesa GL (mesa, the default) or lowered to Vulkan GLSL 4.50 on lavapipe
  // (vulkan, runtime/glsl_vulkan.h).
  const bool vulkan = options.engine == "vulkan";
  if (!options.engine.empty() && options.engine != "mesa" && !vulkan) {
    return static_cast<int>(
        Fail(fmt::format("--engine {}: GLSL shaders run on Mesa GL (engine mesa) or on lavapipe "
                         "(engine vulkan): the reference interpreter runs ARB programs, not GLSL",
                         options.engine),
             Exit::Usage));
  }
  for (const std::string& file : common.files) {
    CommonOptions one;
    one.files = {file};
    if (!ExecFilesAreGlsl(one) && common.stage.empty()) {
      return static_cast<int>(
          Fail(fmt::format("'{}' is not a GLSL shader: exec runs GLSL shaders or ARB programs, not "
                           "both at once",
                           file),
               Exit::Usage));
    }
  }
  runtime::Backend backend = runtime::Backend::OSMesa;
  if (!runtime::ParseBackend(options.mesa->backend, &backend) ||
      !runtime::IsSupportedMesaDriver(options.mesa->driver)) {
    return static_cast<int>(Fail(fmt::format("unknown backend '{}' or driver '{}'",
                                             options.mesa->backend, options.mesa->driver),
                                 Exit::Usage));
  }
  const bool json = common.format == "json";
  Loaded loaded;
  const Exit exit = LoadShaders(options, &loaded);
  if (!json) PrintLoadReports(loaded.reports, common);
  if (exit != Exit::Ok) {
    if (json && exit == Exit::Rejected) PrintJson(loaded, nullptr, {});
    return static_cast<int>(exit);
  }
  runtime::GlslExecInputs inputs;
  std::vector<std::string> warnings;
  if (!BuildInputs(options, loaded, &inputs, &warnings)) return static_cast<int>(Exit::Usage);
  if (!json) {
    for (const std::string& w : warnings) fmt::print(stderr, "arbiter: warning: {}\n", w);
  }
  runtime::GlslShaders shaders;
  if (loaded.vertex != nullptr) {
    shaders.vertex = std::string(loaded.vertex->text());
    shaders.vertex_reflection = &loaded.vertex_reflection;
  }
  if (loaded.fragment != nullptr) {
    shaders.fragment = std::string(loaded.fragment->text());
    shaders.fragment_reflection = &loaded.fragment_reflection;
  }
  runtime::ExecOptions exec;
  exec.backend = backend;
  exec.driver = options.mesa->driver;
  runtime::WorkerLimits limits;
  limits.timeout_ms = options.mesa->timeout_ms;
  limits.memory_bytes = static_cast<uint64_t>(options.mesa->memory_mib) << 20;
  runtime::GlslRunResult result;
  std::string error;
  if (vulkan) {
    std::string not_applicable;
    const runtime::WorkerStatus status =
        runtime::RunGlslVulkanInWorker(limits, shaders, inputs, &result, &not_applicable, &error);
    if (!not_applicable.empty()) {
      return static_cast<int>(Fail(
          fmt::format("--engine vulkan: {} (--engine mesa runs it)", not_applicable), Exit::Usage));
    }
    if (status != runtime::WorkerStatus::Ok) {
      return static_cast<int>(Fail(fmt::format("vulkan (lavapipe): {}", error), Exit::Environment));
    }
  } else if (runtime::RunGlslInWorker(exec, limits, shaders, inputs, &result, &error) !=
             runtime::WorkerStatus::Ok) {
    return static_cast<int>(
        Fail(fmt::format("mesa ({}, {}): {}", options.mesa->backend, options.mesa->driver, error),
             Exit::Environment));
  }
  if (!result.usage_error.empty()) return static_cast<int>(Fail(result.usage_error, Exit::Usage));
  if (json) {
    PrintJson(loaded, &result, warnings, vulkan ? "vulkan" : "mesa");
  } else {
    for (const std::string& note : result.notes) fmt::print(stderr, "arbiter: note: {}\n", note);
    PrintText(result);
  }
  return static_cast<int>(Exit::Ok);
}

}  // namespace arbiter::cli
