// arbiter verify: run each program on the reference interpreter, on Mesa as ARB and on Mesa
// as its GLSL translation over generated inputs, and report every disagreement.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>

#include "arbiter/arbvp/deviations.h"
#include "arbiter/arbvp/emit_mutation.h"
#include "arbiter/arbvp/exec_io.h"
#include "arbiter/runtime/glsl_verify.h"
#include "arbiter/runtime/mesa.h"
#include "arbiter/runtime/verify.h"
#include "cli.h"
#include "load_arb.h"
#include "options.h"
#include "verify_glsl.h"

namespace arbiter::cli {
namespace {

struct VerifyCommandOptions {
  CommonOptions common;
  // As given; each kind of input takes its own engines, or its defaults when none is named.
  std::vector<std::string> engines;
  int vectors = 64;
  uint64_t seed = 1;
  bool pair = false;
  int max_reports = 10;
  MesaOptions mesa{.timeout_ms = 20000};
  std::string mutation = "none";  // test-only (hidden)
};

std::string Component(const runtime::Disagreement& d) {
  if (!d.label.empty()) return d.label;
  if (d.component < 0) return d.reg;
  return fmt::format("{}.{}", d.reg, "xyzw"[d.component]);
}

// Every engine name --engines takes, in report order.
std::vector<std::string> AllEngines() {
  std::vector<std::string> all{runtime::kEngineRef, runtime::kEngineMesaArb,
                               runtime::kEngineMesaGlsl};
  for (const runtime::TargetEngineInfo& t : runtime::kTargetEngines) all.emplace_back(t.name);
  for (const std::string& e : runtime::GlslEngineNames()) all.push_back(e);
  return all;
}

bool IsGlslEngine(const std::string& name) {
  const std::vector<std::string>& glsl = runtime::GlslEngineNames();
  return std::find(glsl.begin(), glsl.end(), name) != glsl.end();
}

std::string Values(const runtime::Disagreement& d) {
  std::string out;
  for (const std::string& engine : AllEngines()) {
    auto it = d.values.find(engine);
    if (it == d.values.end()) continue;
    if (!out.empty()) out += ", ";
    out += fmt::format("{} {}", engine, arbvp::FormatFloat(it->second));
    if (engine == runtime::kEngineRef && d.component >= 0) {
      out += fmt::format(" (tolerance {})", arbvp::FormatFloat(d.tolerance));
    }
  }
  // GLSL: no reference; the engines' values and the difference the model allows.
  if (!d.label.empty()) out += fmt::format(", tolerance {}", arbvp::FormatFloat(d.tolerance));
  return out;
}

std::string Summary(const runtime::Verdict& v) {
  size_t undefined = 0;
  for (const auto& [reason, count] : v.undefined) undefined += count;
  size_t deviations = 0;
  for (const auto& [name, count] : v.deviations) deviations += count;
  return fmt::format(
      "{} vectors, {} comparisons, not compared: {} undefined, {} unstable, {} known deviations",
      v.vectors, v.compared, undefined, v.unstable, deviations);
}

void PrintText(const std::vector<runtime::Verdict>& verdicts, const VerifyCommandOptions& options,
               const std::string& setup, size_t rejected, size_t skipped) {
  std::string out;
  size_t agree = 0;
  size_t disagree = 0;
  size_t errors = 0;
  size_t not_applicable = 0;
  for (const runtime::Verdict& v : verdicts) {
    if (!v.error.empty()) {
      ++errors;
      out += fmt::format("{}: error: {}\n", v.name, v.error);
    } else if (v.disagreements.empty()) {
      ++agree;
      out += fmt::format("{}: agree ({})\n", v.name, Summary(v));
    }
    if (!v.disagreements.empty()) {
      ++disagree;
      out +=
          fmt::format("{}: {} disagreement(s) ({})\n", v.name, v.disagreements.size(), Summary(v));
    }
    size_t shown = 0;
    for (const runtime::Disagreement& d : v.disagreements) {
      if (shown++ == static_cast<size_t>(options.max_reports)) {
        out += fmt::format("  ... and {} more\n", v.disagreements.size() - options.max_reports);
        break;
      }
      std::string engines;
      for (const std::string& e : d.engines) engines += (engines.empty() ? "" : ", ") + e;
      out += fmt::format("  {} vector {}: {}: {}{} [differs: {}]\n", d.batch, d.vector,
                         Component(d), d.what.empty() ? "" : d.what + "; ", Values(d), engines);
      for (const std::string& input : d.inputs) out += "      " + input + "\n";
    }
    size_t listed = 0;
    for (const auto& [reason, count] : v.undefined) {
      if (listed++ == 3) {
        out += fmt::format("  undefined: ... and {} more reasons\n", v.undefined.size() - 3);
        break;
      }
      out += fmt::format("  undefined ({} components): {}\n", count, reason);
    }
    for (const auto& [name, count] : v.deviations) {
      out += fmt::format("  known deviation {} ({} components)\n", name, count);
    }
    for (const auto& [engine, why] : v.not_applicable) {
      if (engine == runtime::kGlslProbeName) {
        out += fmt::format("  no {}: {}\n", engine, why);
        continue;
      }
      out += fmt::format("  not applicable on {}: {}\n", engine, why);
      ++not_applicable;
    }
  }
  std::string not_run =
      rejected > 0 ? fmt::format(", {} rejected by the checker (not run)", rejected) : "";
  if (skipped > 0) {
    not_run +=
        fmt::format(", {} with nothing to run (no main(), or several shaders of a stage)", skipped);
  }
  if (not_applicable > 0) {
    not_run += fmt::format(", {} not applicable (a target refuses the program)", not_applicable);
  }
  out += fmt::format("verify: {} program(s): {} agree, {} disagree, {} error(s){} ({})\n",
                     verdicts.size() + rejected, agree, disagree, errors, not_run, setup);
  fmt::print("{}", out);
}

nlohmann::ordered_json VerdictJson(const runtime::Verdict& v, size_t max_reports) {
  nlohmann::ordered_json j;
  j["file"] = v.name;
  j["verdict"] = !v.error.empty() ? "error" : (v.disagreements.empty() ? "agree" : "disagree");
  if (!v.error.empty()) j["error"] = v.error;
  j["vectors"] = v.vectors;
  j["compared"] = v.compared;
  j["undefined"] = v.undefined;
  j["unstable"] = v.unstable;
  j["deviations"] = v.deviations;
  j["disagreement_count"] = v.disagreements.size();
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const runtime::Disagreement& d : v.disagreements) {
    if (list.size() == max_reports) break;
    nlohmann::ordered_json jd = {{"batch", d.batch}, {"vector", d.vector}, {"register", d.reg}};
    if (!d.label.empty()) {
      jd["component"] = d.label;
    } else if (d.component >= 0) {
      jd["component"] = std::string(1, "xyzw"[d.component]);
    }
    if (!d.what.empty()) jd["what"] = d.what;
    if (d.component >= 0) jd["tolerance"] = arbvp::FloatToJson(d.tolerance);
    nlohmann::ordered_json values = nlohmann::ordered_json::object();
    for (const auto& [engine, value] : d.values) values[engine] = arbvp::FloatToJson(value);
    jd["values"] = values;
    jd["differs"] = d.engines;
    jd["inputs"] = d.inputs;
    list.push_back(std::move(jd));
  }
  j["disagreements"] = list;
  if (!v.not_applicable.empty()) j["not_applicable"] = v.not_applicable;
  return j;
}

// The subjects: each program alone, or with --pair one vertex + fragment pair.
bool Subjects(const VerifyCommandOptions& options, const std::vector<const LoadedArb*>& loaded,
              std::vector<runtime::VerifySubject>* subjects) {
  if (!options.pair) {
    for (const LoadedArb* p : loaded) {
      const LoadedArb& l = *p;
      runtime::VerifySubject s;
      s.name = l.input.display_path;
      bool vp = l.checked.program->kind == arbvp::ProgramKind::Vertex;
      (vp ? s.vertex : s.fragment) = l.checked.program.get();
      (vp ? s.vertex_source : s.fragment_source) = l.source.get();
      subjects->push_back(s);
    }
    return true;
  }
  runtime::VerifySubject s;
  for (const LoadedArb* p : loaded) {
    const LoadedArb& l = *p;
    bool vp = l.checked.program->kind == arbvp::ProgramKind::Vertex;
    if (vp ? s.vertex != nullptr : s.fragment != nullptr) return false;
    (vp ? s.vertex : s.fragment) = l.checked.program.get();
    (vp ? s.vertex_source : s.fragment_source) = l.source.get();
  }
  if (!s.vertex || !s.fragment || loaded.size() != 2) return false;
  s.name = loaded[0]->input.display_path + " + " + loaded[1]->input.display_path;
  subjects->push_back(s);
  return true;
}

// The arguments ARB loading takes: named files that are not GLSL, and directories that hold
// ARB programs (a directory of GLSL shaders alone is not an error for it).
std::vector<std::string> ArbArguments(const VerifyCommandOptions& options) {
  std::vector<std::string> out;
  for (const std::string& arg : options.common.files) {
    std::error_code ec;
    if (!std::filesystem::is_directory(arg, ec)) {
      if (!IsVerifyGlslPath(arg)) out.push_back(arg);
      continue;
    }
    for (const Input& input : ExpandInputs({arg}, 1)) {
      if (input.error.empty() && !IsVerifyGlslPath(input.path)) {
        out.push_back(arg);
        break;
      }
    }
  }
  return out;
}

// Verifies the ARB programs of `args`: their verdicts are appended. `loaded` keeps the
// programs the reports point into.
Exit VerifyArb(const VerifyCommandOptions& options, const std::vector<std::string>& args,
               const std::vector<std::string>& engines, std::vector<LoadedArb>* loaded,
               std::vector<runtime::Verdict>* verdicts, std::vector<compiler::FileReport>* reports,
               size_t* rejected, std::string* setup) {
  runtime::VerifyOptions verify;
  if (!runtime::ParseBackend(options.mesa.backend, &verify.exec.backend)) return Exit::Usage;
  verify.exec.driver = options.mesa.driver;
  verify.jobs = static_cast<int>(ResolveJobs(options.common));
  verify.limits.timeout_ms = options.mesa.timeout_ms;
  verify.limits.memory_bytes = static_cast<uint64_t>(options.mesa.memory_mib) << 20;
  verify.generate.random_vectors = options.vectors;
  verify.generate.seed = options.seed;
  auto has = [&](const char* e) {
    return std::find(engines.begin(), engines.end(), e) != engines.end();
  };
  verify.mesa_arb = has(runtime::kEngineMesaArb);
  verify.mesa_glsl = has(runtime::kEngineMesaGlsl);
  for (const runtime::TargetEngineInfo& t : runtime::kTargetEngines) {
    if (has(t.name)) verify.targets.emplace_back(t.name);
  }
  if (!has(runtime::kEngineRef) ||
      !(verify.mesa_arb || verify.mesa_glsl || !verify.targets.empty())) {
    fmt::print(stderr,
               "arbiter: error: --engines: ref (the specification, every engine's reference) "
               "and at least one of mesa-arb, mesa-glsl, mesa-glsl330, mesa-es300, "
               "mesa-es100, vulkan-spirv\n");
    return Exit::Usage;
  }
  arbvp::Mutation mutation = arbvp::Mutation::None;
  if (!arbvp::LookupMutation(options.mutation, &mutation)) {
    fmt::print(stderr, "arbiter: error: unknown mutation '{}'\n", options.mutation);
    return Exit::Usage;
  }
  verify.emit = arbvp::WithMutation(verify.emit, mutation);

  CommonOptions common = options.common;
  common.files = args;
  Exit exit = LoadArbPrograms(common, "verify", loaded, reports);
  if (exit == Exit::Usage) return exit;
  for (const LoadedArb& l : *loaded) *rejected += l.ok() ? 0 : 1;
  std::vector<const LoadedArb*> valid;
  for (const LoadedArb& l : *loaded) {
    if (l.ok()) valid.push_back(&l);
  }
  std::vector<runtime::VerifySubject> subjects;
  if (!Subjects(options, valid, &subjects)) {
    fmt::print(stderr,
               "arbiter: error: --pair takes one vertex program and one fragment program\n");
    return Exit::Usage;
  }
  for (runtime::Verdict& v : runtime::Verify(subjects, verify)) verdicts->push_back(std::move(v));
  *setup = fmt::format("{} via {}", options.mesa.driver, options.mesa.backend);
  // The target engines make EGL core and ES contexts whatever --backend says; vulkan-spirv
  // runs on lavapipe whatever --driver says.
  const bool vulkan = has(runtime::kEngineVulkanSpirv);
  if (verify.targets.size() > (vulkan ? 1u : 0u)) *setup += " (target engines via egl)";
  if (vulkan) *setup += " (vulkan-spirv on lavapipe)";
  return exit;
}

// Verifies the GLSL shaders of the arguments: their verdicts are appended.
// `loaded` keeps the shaders the reports point into.
Exit VerifyGlsl(const VerifyCommandOptions& options, const std::vector<std::string>& engines,
                LoadedGlsl* loaded_out, std::vector<runtime::Verdict>* verdicts,
                std::vector<compiler::FileReport>* reports, size_t* rejected, std::string* setup) {
  LoadedGlsl& loaded = *loaded_out;
  Exit exit = LoadGlslSubjects(options.common.files, options.pair, &loaded);
  if (exit == Exit::Usage) {
    fmt::print(stderr, "arbiter: error: --pair takes one vertex shader and one fragment shader\n");
    return exit;
  }
  for (compiler::FileReport& r : loaded.reports) reports->push_back(std::move(r));
  *rejected += loaded.rejected;
  if (loaded.subjects.empty()) return exit;
  runtime::GlslVerifyOptions verify;
  verify.engines = engines;
  if (!runtime::ParseBackend(options.mesa.backend, &verify.backend)) return Exit::Usage;
  verify.jobs = static_cast<int>(ResolveJobs(options.common));
  verify.limits.timeout_ms = options.mesa.timeout_ms;
  verify.limits.memory_bytes = static_cast<uint64_t>(options.mesa.memory_mib) << 20;
  verify.generate.random_vectors = options.vectors;
  verify.generate.seed = options.seed;
  for (runtime::Verdict& v : runtime::VerifyGlsl(loaded.subjects, verify)) {
    verdicts->push_back(std::move(v));
  }
  *setup = fmt::format(
      "GLSL engines {} (Mesa's GL drivers via {}{})", fmt::join(engines, ", "),
      options.mesa.backend,
      std::find(engines.begin(), engines.end(), runtime::kGlslEngineVulkan) != engines.end()
          ? ", vulkan on lavapipe"
          : "");
  return exit;
}

int RunVerify(const VerifyCommandOptions& options) {
  std::vector<std::string> arb_engines;
  std::vector<std::string> glsl_engines;
  for (const std::string& e : options.engines) {
    (IsGlslEngine(e) ? glsl_engines : arb_engines).push_back(e);
  }
  if (arb_engines.empty()) {
    arb_engines = {runtime::kEngineRef, runtime::kEngineMesaArb, runtime::kEngineMesaGlsl};
  }
  if (glsl_engines.empty()) glsl_engines = runtime::GlslEngineNames();
  if (glsl_engines.size() < 2) {
    fmt::print(stderr,
               "arbiter: error: --engines: GLSL shaders need two engines to compare "
               "(softpipe, llvmpipe, vulkan)\n");
    return static_cast<int>(Exit::Usage);
  }

  std::vector<runtime::Verdict> verdicts;
  std::vector<compiler::FileReport> reports;
  size_t rejected = 0;
  Exit exit = Exit::Ok;
  std::vector<std::string> setups;
  const std::vector<std::string> arb_args = ArbArguments(options);
  std::vector<LoadedArb> arb_loaded;  // the reports point into these
  if (!arb_args.empty()) {
    std::string setup;
    exit = VerifyArb(options, arb_args, arb_engines, &arb_loaded, &verdicts, &reports, &rejected,
                     &setup);
    if (exit == Exit::Usage) return static_cast<int>(exit);
    if (!setup.empty()) setups.push_back(setup);
  }
  LoadedGlsl glsl_loaded;
  {
    std::string setup;
    const Exit glsl =
        VerifyGlsl(options, glsl_engines, &glsl_loaded, &verdicts, &reports, &rejected, &setup);
    if (glsl == Exit::Usage) return static_cast<int>(glsl);
    exit = Worse(exit, glsl);
    if (!setup.empty()) setups.push_back(setup);
  }
  if (options.common.format != "json") PrintLoadReports(reports, options.common);
  for (const runtime::Verdict& v : verdicts) {
    if (!v.error.empty()) exit = Worse(exit, Exit::Environment);
    if (!v.disagreements.empty()) exit = Worse(exit, Exit::Rejected);
  }
  std::string setup = fmt::format("seed {}, {} random vectors", options.seed, options.vectors);
  for (const std::string& s : setups) setup += ", " + s;
  if (options.common.format == "json") {
    nlohmann::ordered_json j;
    j["seed"] = options.seed;
    j["random_vectors"] = options.vectors;
    j["driver"] = options.mesa.driver;
    j["backend"] = options.mesa.backend;
    j["engines"] = options.engines.empty() ? arb_engines : options.engines;
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const runtime::Verdict& v : verdicts) {
      list.push_back(VerdictJson(v, static_cast<size_t>(options.max_reports)));
    }
    j["programs"] = list;
    j["diagnostics"] = DiagnosticsJson(reports);
    // A path that is not UTF-8 becomes U+FFFD instead of throwing.
    fmt::print("{}\n", j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
  } else {
    PrintText(verdicts, options, setup, rejected, glsl_loaded.skipped);
  }
  return static_cast<int>(exit);
}

}  // namespace

// Adds the `verify` subcommand to `app`; the returned function runs it once it is parsed.
std::function<int()> AddVerifyCommand(CLI::App* app) {
  auto options = std::make_shared<VerifyCommandOptions>();
  CLI::App* cmd = app->add_subcommand(
      "verify",
      "run ARB programs on the reference interpreter, on Mesa and as their translations, and "
      "GLSL shaders on Mesa's two drivers and through glslang on lavapipe, over edge and random "
      "inputs, and report every disagreement");
  cmd->footer(
      "Each program or shader is verified alone (--pair: one vertex and one fragment program or "
      "shader together; a .shader_test's shaders together). "
      "Components the specs leave undefined, components within rounding of a discontinuity and "
      "known Mesa deviations are reported, not compared. Exit 1 on a disagreement. The "
      "tolerance model: docs/verify.md.");
  CommonOptions& common = options->common;
  cmd->add_option("files", common.files,
                  "ARB programs, GLSL shaders (.vert .frag ...) and .shader_test files "
                  "(directories are searched)")
      ->required();
  cmd->add_option("--engines", options->engines,
                  "ref and the Mesa engines to compare with it: mesa-arb (the program), "
                  "mesa-glsl (its translation), mesa-glsl330, mesa-es300, mesa-es100 (the "
                  "target translations on EGL core and ES contexts), vulkan-spirv (the vk450 "
                  "translation as SPIR-V on lavapipe); for GLSL shaders two or more of "
                  "softpipe and llvmpipe (Mesa's GLSL compiler on each driver) and vulkan "
                  "(glslang to SPIR-V on lavapipe), the first the baseline (default: all "
                  "three)")
      ->delimiter(',')
      ->check(CLI::IsMember(AllEngines()));
  cmd->add_option("--vectors", options->vectors, "random input vectors besides the edge vectors")
      ->check(CLI::Range(0, 100000));
  cmd->add_option("--seed", options->seed, "seed of the random inputs");
  cmd->add_flag("--pair", options->pair, "verify a vertex and a fragment program as a pair");
  cmd->add_option("--max-reports", options->max_reports, "disagreements printed per program (text)")
      ->check(CLI::NonNegativeNumber);
  AddMesaOptions(cmd, &options->mesa, "of the Mesa engines per program");
  AddFormatOption(cmd, &common.format, {"text", "json"});
  AddColorOption(cmd, &common.color);
  AddStageOption(cmd, &common.stage, /*glsl=*/false);
  AddJobsOption(cmd, &common.jobs, "worker processes");
  cmd->add_option("--mutation", options->mutation)->group("");
  return [options] { return RunVerify(*options); };
}

}  // namespace arbiter::cli
