// arbiter exec: run ARB programs on the reference interpreter and/or Mesa and print every
// output register per input vector.
#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>

#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/exec_io.h"
#include "arbiter/arbvp/interpret.h"
#include "arbiter/runtime/mesa.h"
#include "arbiter/runtime/worker.h"
#include "cli.h"
#include "exec_glsl.h"
#include "load_arb.h"
#include "options.h"

namespace arbiter::cli {
namespace {

struct ExecCommandOptions {
  CommonOptions common;  // --format --color --error-limit --stage, the files
  std::string engine;    // "" when not given: ref for ARB programs, mesa for GLSL shaders
  MesaOptions mesa;
  std::vector<std::string> set;
  std::vector<std::string> uniforms;  // GLSL only
  bool pair = false;
  std::vector<std::string> state;
  std::vector<std::string> textures;
  std::string vectors;
};

struct EngineRun {
  std::string name;  // "ref", "mesa"
  std::vector<arbvp::VectorResult> results;
};

// The programs to run: one alone, or a vertex program and a fragment program as a pair.
bool PickPrograms(const std::vector<LoadedArb>& loaded, const LoadedArb** vertex,
                  const LoadedArb** fragment) {
  *vertex = nullptr;
  *fragment = nullptr;
  for (const LoadedArb& p : loaded) {
    const LoadedArb** slot =
        p.checked.program->kind == arbvp::ProgramKind::Vertex ? vertex : fragment;
    if (*slot) return false;
    *slot = &p;
  }
  return *vertex || *fragment;
}

bool BuildInputs(const ExecCommandOptions& options, arbvp::ExecInputs* inputs) {
  std::string error;
  if (!options.vectors.empty()) {
    std::string text;
    if (!compiler::ReadFileBytes(options.vectors, &text, &error) ||
        !arbvp::ParseVectorsJson(text, inputs, &error)) {
      fmt::print(stderr, "arbiter: error: {}: {}\n", options.vectors, error);
      return false;
    }
  }
  if (inputs->vectors.empty()) inputs->vectors.emplace_back();
  // Flags apply on top of the file, to every vector.
  for (const std::string& state : options.state) {
    if (!state.starts_with("state.")) {
      fmt::print(stderr, "arbiter: error: --state '{}': names start with 'state.'\n", state);
      return false;
    }
  }
  for (const auto* list : {&options.state, &options.set}) {
    for (const std::string& assignment : *list) {
      for (arbvp::InputVector& v : inputs->vectors) {
        if (!arbvp::ApplyAssignment(assignment, inputs, &v, &error)) {
          fmt::print(stderr, "arbiter: error: {}\n", error);
          return false;
        }
      }
    }
  }
  for (const std::string& flag : options.textures) {
    if (!arbvp::ApplyTextureFlag(flag, inputs, &error)) {
      fmt::print(stderr, "arbiter: error: --texture {}\n", error);
      return false;
    }
  }
  return true;
}

std::string ComponentCell(const arbvp::OutputRegister& o, size_t c) {
  if (!(o.written & (1u << c))) return "-";
  std::string text = arbvp::FormatFloat(o.value[c]);
  if (!o.undefined[c].empty()) text += "?";
  return text;
}

const arbvp::OutputRegister* FindOutput(const arbvp::VectorResult& r, const std::string& name) {
  for (const arbvp::OutputRegister& o : r.outputs) {
    if (o.name == name) return &o;
  }
  return nullptr;
}

// Text: one block per vector, one line per register and engine; '*' marks a component
// that differs from the first engine's, '?' one the specs leave undefined.
void PrintText(const std::vector<EngineRun>& runs, const std::vector<arbvp::Difference>& diffs) {
  std::string out;
  std::vector<std::string> notes;
  const size_t vectors = runs.front().results.size();
  const bool several = runs.size() > 1;
  for (size_t v = 0; v < vectors; ++v) {
    out += fmt::format("vector {}\n", v);
    std::vector<std::string> names;
    for (const EngineRun& run : runs) {
      const arbvp::VectorResult& r = run.results[v];
      if (r.killed) {
        out += fmt::format("  {:<28}{}killed\n", "(fragment)", several ? run.name + "  " : "");
      }
      for (const arbvp::OutputRegister& o : r.outputs) {
        if (std::find(names.begin(), names.end(), o.name) == names.end()) names.push_back(o.name);
      }
    }
    for (const std::string& name : names) {
      for (size_t e = 0; e < runs.size(); ++e) {
        const arbvp::OutputRegister* o = FindOutput(runs[e].results[v], name);
        std::string line = fmt::format("  {:<28}", e == 0 || !several ? name : "");
        if (several) line += fmt::format("{:<6}", runs[e].name);
        for (size_t c = 0; c < 4; ++c) {
          std::string cell = o ? ComponentCell(*o, c) : "-";
          bool differs = false;
          for (const arbvp::Difference& d : diffs) {
            differs |= e > 0 && d.vector == v && d.reg == name &&
                       (d.component == static_cast<int>(c) || d.component < 0);
          }
          line += fmt::format(" {:>14}", cell + (differs ? "*" : ""));
          if (o && !o->undefined[c].empty() && e == 0) {
            notes.push_back(
                fmt::format("vector {} {}.{}: {}", v, name, "xyzw"[c], o -> undefined[c]));
          }
        }
        out += line + "\n";
      }
    }
  }
  if (!notes.empty()) {
    out += "undefined (not compared):\n";
    for (const std::string& n : notes) out += "  " + n + "\n";
  }
  if (several) {
    out += diffs.empty() ? "the engines agree on every defined component\n"
                         : fmt::format("{} difference(s) between {} and {}\n", diffs.size(),
                                       runs[0].name, runs[1].name);
  }
  fmt::print("{}", out);
}

void PrintJson(const std::vector<EngineRun>& runs, const std::vector<arbvp::Difference>& diffs,
               const std::vector<std::string>& files,
               const std::vector<compiler::FileReport>& reports,
               const std::vector<std::string>& warnings = {}) {
  nlohmann::ordered_json j;
  j["files"] = files;
  nlohmann::ordered_json engines = nlohmann::ordered_json::object();
  for (const EngineRun& run : runs) engines[run.name] = arbvp::ResultsToJson(run.results);
  j["results"] = engines;
  if (runs.size() > 1) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const arbvp::Difference& d : diffs) {
      nlohmann::ordered_json jd = {{"vector", d.vector}, {"register", d.reg}};
      if (d.component >= 0) {
        jd["component"] = std::string(1, "xyzw"[d.component]);
        jd[runs[0].name] = arbvp::FloatToJson(d.a);
        jd[runs[1].name] = arbvp::FloatToJson(d.b);
      } else {
        jd["what"] = d.what;
      }
      list.push_back(std::move(jd));
    }
    j["differences"] = list;
  }
  // A path that is not UTF-8 becomes U+FFFD instead of throwing.
  j["diagnostics"] = DiagnosticsJson(reports);
  j["warnings"] = warnings;
  fmt::print("{}\n", j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
}

int RunExec(const ExecCommandOptions& given) {
  if (ExecFilesAreGlsl(given.common)) {
    ExecGlslOptions glsl{&given.common, given.engine,   &given.mesa,   given.set, given.uniforms,
                         given.state,   given.textures, given.vectors, given.pair};
    return RunExecGlsl(glsl);
  }
  if (given.pair) {
    fmt::print(stderr,
               "arbiter: error: --pair is for GLSL shaders: a vertex and a fragment program "
               "given together always run as a pair\n");
    return static_cast<int>(Exit::Usage);
  }
  if (!given.uniforms.empty()) {
    fmt::print(stderr,
               "arbiter: error: --uniform sets GLSL uniforms; an ARB program's parameters are "
               "--set program.local[N]=.. and program.env[N]=..\n");
    return static_cast<int>(Exit::Usage);
  }
  ExecCommandOptions options = given;
  if (options.engine.empty()) options.engine = "ref";
  if (options.engine == "vulkan") {
    fmt::print(stderr,
               "arbiter: error: --engine vulkan runs GLSL shaders; ARB programs run on ref, mesa "
               "or all (arbiter verify runs their translations on Vulkan)\n");
    return static_cast<int>(Exit::Usage);
  }
  runtime::Backend backend = runtime::Backend::OSMesa;
  if (!runtime::ParseBackend(options.mesa.backend, &backend) ||
      !runtime::IsSupportedMesaDriver(options.mesa.driver)) {
    fmt::print(stderr, "arbiter: error: unknown backend '{}' or driver '{}'\n",
               options.mesa.backend, options.mesa.driver);
    return static_cast<int>(Exit::Usage);
  }
  // A program file is never NAME=VALUE: that is a second value given to one --set.
  for (const std::string& file : options.common.files) {
    std::error_code ec;
    if (file.find('=') != std::string::npos && !std::filesystem::exists(file, ec)) {
      fmt::print(stderr,
                 "arbiter: error: '{}' is not a file: --set, --state and --texture take one "
                 "NAME=VALUE each (--set a=1 --set b=2)\n",
                 file);
      return static_cast<int>(Exit::Usage);
    }
  }
  std::vector<LoadedArb> loaded;
  std::vector<compiler::FileReport> reports;
  Exit exit = LoadArbPrograms(options.common, "exec", &loaded, &reports);
  const bool json = options.common.format == "json";
  if (!json) PrintLoadReports(reports, options.common);
  if (exit != Exit::Ok) {
    // JSON: the diagnostics, and no results.
    if (json && exit != Exit::Usage) {
      std::vector<std::string> files;
      files.reserve(loaded.size());
      for (const LoadedArb& p : loaded) files.push_back(p.input.display_path);
      PrintJson({}, {}, files, reports);
    }
    return static_cast<int>(exit);
  }
  const LoadedArb* vertex = nullptr;
  const LoadedArb* fragment = nullptr;
  if (!PickPrograms(loaded, &vertex, &fragment)) {
    fmt::print(stderr,
               "arbiter: error: exec runs one program, or one vertex program and one fragment "
               "program as a pair\n");
    return static_cast<int>(Exit::Usage);
  }
  arbvp::ExecInputs inputs;
  if (!BuildInputs(options, &inputs)) return static_cast<int>(Exit::Usage);
  std::vector<const arbvp::Program*> run_programs;
  for (const LoadedArb* p : {vertex, fragment}) {
    if (p != nullptr) run_programs.push_back(p->checked.program.get());
  }
  const std::vector<std::string> warnings =
      arbvp::UnusedInputWarnings(run_programs, options.set, inputs);
  if (!json) {
    for (const std::string& w : warnings) fmt::print(stderr, "arbiter: warning: {}\n", w);
  }

  std::vector<EngineRun> runs;
  if (options.engine == "ref" || options.engine == "all") {
    EngineRun run{"ref", {}};
    if (vertex && fragment) {
      run.results = arbvp::InterpretPair(*vertex->checked.program, *fragment->checked.program,
                                         inputs, vertex->source.get(), fragment->source.get());
    } else {
      const LoadedArb* p = vertex ? vertex : fragment;
      run.results = arbvp::Interpret(*p->checked.program, inputs, p->source.get());
    }
    runs.push_back(std::move(run));
  }
  if (options.engine == "mesa" || options.engine == "all") {
    runtime::ExecOptions exec;
    exec.backend = backend;
    exec.driver = options.mesa.driver;
    runtime::WorkerLimits limits;
    limits.timeout_ms = options.mesa.timeout_ms;
    limits.memory_bytes = static_cast<uint64_t>(options.mesa.memory_mib) << 20;
    runtime::ArbPrograms programs;
    programs.vertex = vertex ? vertex->checked.program.get() : nullptr;
    programs.fragment = fragment ? fragment->checked.program.get() : nullptr;
    EngineRun run{"mesa", {}};
    std::string error;
    if (runtime::RunArbInWorker(exec, limits, programs, inputs, &run.results, &error) !=
        runtime::WorkerStatus::Ok) {
      fmt::print(stderr, "arbiter: error: mesa ({}, {}): {}\n", options.mesa.backend,
                 options.mesa.driver, error);
      return static_cast<int>(Exit::Environment);
    }
    runs.push_back(std::move(run));
  }

  std::vector<arbvp::Difference> diffs;
  if (runs.size() > 1) diffs = arbvp::CompareResults(runs[0].results, runs[1].results);
  std::vector<std::string> files;
  files.reserve(loaded.size());
  for (const LoadedArb& p : loaded) files.push_back(p.source->path());
  if (options.common.format == "json") {
    PrintJson(runs, diffs, files, reports, warnings);
  } else {
    PrintText(runs, diffs);
  }
  return static_cast<int>(diffs.empty() ? Exit::Ok : Exit::Rejected);
}

}  // namespace

// Adds the `exec` subcommand to `app`; the returned function runs it once it is parsed.
std::function<int()> AddExecCommand(CLI::App* app) {
  auto options = std::make_shared<ExecCommandOptions>();
  CLI::App* exec = app->add_subcommand(
      "exec",
      "run ARB programs on the reference interpreter or Mesa, or GLSL shaders on Mesa or lavapipe "
      "(Vulkan), and print every output");
  exec->footer(
      "A vertex program and a fragment program (or a vertex and a fragment shader) given together "
      "run as a pair. With --engine all, "
      "the exit code is 1 when the engines differ on a component the specs define. Inputs: "
      "docs/exec.md.");
  CommonOptions& common = options->common;
  exec->add_option("files", common.files,
                   "one program or shader, or a vertex and a fragment program or shader")
      ->required();
  exec->add_option("--engine", options->engine,
                   "ref (the reference interpreter, the default for ARB programs), mesa (Mesa GL, "
                   "the default for GLSL shaders), all (ref and mesa, differences marked), or "
                   "vulkan (GLSL shaders lowered to Vulkan GLSL 4.50 and run on lavapipe)")
      ->check(CLI::IsMember({"ref", "mesa", "all", "vulkan"}));
  AddRepeatedOption(
      exec, "--set", &options->set, "NAME=V1,..",
      "an input for every vector, one per --set (vertex.attrib[1]=1,2,3,4, "
      "fragment.texcoord[0]=.5,.5, program.local[0]=..., vertex.program.env[2]=...; GLSL: "
      "gl_Vertex=1,2,3,1, gl_MultiTexCoord0=.., a user attribute tangent=.., and for "
      "a fragment shader alone gl_Color=.., gl_TexCoord[0]=.., a varying)");
  AddRepeatedOption(exec, "--state", &options->state, "NAME=V1,..",
                    "GL state, one per --state (state.light[0].diffuse=1,0,0,1, "
                    "state.matrix.modelview=<16 numbers, row-major>, state.fog.density=2, ...)");
  AddRepeatedOption(exec, "--texture", &options->textures, "UNIT=TARGET:PATTERN..",
                    "one per --texture: UNIT=TARGET:PATTERN[:WxH[xD]][:nearest|linear]"
                    "[:repeat|clamp|mirror], e.g. 0=2D:checker:4x4:linear (patterns: checker, "
                    "gradient, depth-gradient, depth-gradient-compare)");
  AddRepeatedOption(exec, "--uniform", &options->uniforms, "NAME=V1,..",
                    "GLSL: a user uniform, one per --uniform (lightDir=0,0,1, w[2]=.5, "
                    "light.pos=1,2,3, m=<N*N numbers, column by column>, tex=1 for a sampler's "
                    "texture unit)");
  exec->add_flag("--pair", options->pair,
                 "GLSL: run the vertex and the fragment shader as one program (implied by two "
                 "files)");
  exec->add_option("--vectors", options->vectors,
                   "a JSON file of inputs: {\"set\": {...}, \"textures\": {...}, \"vectors\": "
                   "[{...}, ...]} (docs/exec.md)");
  AddFormatOption(exec, &common.format, {"text", "json"});
  AddColorOption(exec, &common.color);
  AddStageOption(exec, &common.stage, /*glsl=*/true);
  AddErrorLimitOption(exec, &common.error_limit);
  AddMesaOptions(exec, &options->mesa, "of the Mesa worker");
  return [options] { return RunExec(*options); };
}

}  // namespace arbiter::cli
