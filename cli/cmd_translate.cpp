// arbiter translate: ARB programs to GLSL 1.10, each translation checked by glslang before
// it is written (a failure is a translator bug: exit 3, nothing written).
#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <set>

#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/emit.h"
#include "arbiter/arbvp/emit_mutation.h"
#include "arbiter/runtime/translate.h"
#include "cli.h"
#include "load_arb.h"
#include "options.h"
#include "translate_targets.h"

namespace arbiter::cli {
namespace {

namespace fs = std::filesystem;

struct TranslateCommandOptions {
  CommonOptions common;  // the files, --stage, --color, --error-limit, --limits
  std::string output;    // -o
  std::string bindings;  // --bindings
  bool pair = false;
  bool no_comments = false;
  std::string target = "glsl110";  // --target
  std::string state;               // --state: "builtins", "uniforms" or "" (the target's)
  std::string mutation = "none";   // test-only: --mutation (hidden)
};

// One unit of output: a program alone, or a pair.
struct Job {
  const LoadedArb* vertex = nullptr;
  const LoadedArb* fragment = nullptr;
  std::string stem;  // output name without extension, for directory outputs
};

std::string Stem(const Input& input) {
  if (input.path == "-") return "stdin";
  return fs::path(input.path).stem().string();
}

// What one job prints, kept until every job before it has printed (output in input order
// whatever -j).
struct Outcome {
  Exit exit = Exit::Ok;
  std::string out;  // stdout
  std::string err;  // stderr
};

// Where a job's files go: `base` + ".vert"/".frag", and the binding map, when writing files.
struct Destination {
  bool to_stdout = true;
  std::string base;      // path without extension
  std::string bindings;  // the bindings file ("" for none)
};

Destination Place(const TranslateCommandOptions& options, const Job& job, bool several) {
  Destination d;
  if (!options.output.empty()) {
    d.to_stdout = false;
    if (several) {
      d.base = (fs::path(options.output) / job.stem).string();
    } else {
      fs::path p(options.output);
      std::string ext = p.extension().string();
      if (ext == ".spv" || ext == ".hlsl" || ext == ".metal") {
        p = p.parent_path() / p.stem();  // a.vert.spv: a.vert
        ext = p.extension().string();
      }
      d.base = (ext == ".vert" || ext == ".frag" || ext == ".glsl" || ext == ".vs" || ext == ".fs")
                   ? (p.parent_path() / p.stem()).string()
                   : options.output;
    }
  }
  if (!options.bindings.empty()) {
    // Named after the shader file: a.vp and a.fp in one directory must not share a map.
    const std::string shader = job.stem + (job.vertex ? ".vert" : ".frag");
    d.bindings = several ? (fs::path(options.bindings) / (shader + ".bindings.json")).string()
                         : options.bindings;
  }
  return d;
}

// The output file of one shader: exactly -o's path for a single program alone.
std::string ShaderPath(const TranslateCommandOptions& options, const Destination& d, bool several,
                       const Job& job, bool vertex) {
  if (!several && !(job.vertex && job.fragment)) return options.output;
  return d.base + (vertex ? ".vert" : ".frag") +
         std::string(LookupOutputTarget(options.target)->extension);
}

Outcome RunJob(const TranslateCommandOptions& options, const Job& job, bool several) {
  Outcome outcome;
  arbvp::EmitOptions emit;
  emit.comments = !options.no_comments;
  arbvp::Mutation mutation = arbvp::Mutation::None;
  arbvp::LookupMutation(options.mutation, &mutation);  // RunTranslate checked the name
  emit = arbvp::WithMutation(emit, mutation);
  if (options.state == "uniforms") emit.state = arbvp::StateSource::Uniforms;
  const OutputTarget& target = *LookupOutputTarget(options.target);
  const bool self_check = target.dialect == arbvp::EmitTarget::Glsl110;
  runtime::CheckedTranslation t;
  if (!self_check) {
    TargetTranslation tt =
        TranslateForTarget(target, job.vertex ? job.vertex->checked.program.get() : nullptr,
                           job.fragment ? job.fragment->checked.program.get() : nullptr, emit,
                           job.vertex ? job.vertex->source.get() : nullptr,
                           job.fragment ? job.fragment->source.get() : nullptr);
    t.ok = tt.ok;
    t.refused = tt.refused;
    t.error = std::move(tt.error);
    t.vertex = std::move(tt.vertex);
    t.fragment = std::move(tt.fragment);
    t.bindings = std::move(tt.bindings);
  } else {
    t = runtime::TranslateChecked(job.vertex ? job.vertex->checked.program.get() : nullptr,
                                  job.fragment ? job.fragment->checked.program.get() : nullptr,
                                  emit, job.vertex ? job.vertex->source.get() : nullptr,
                                  job.fragment ? job.fragment->source.get() : nullptr);
  }
  std::string name = job.vertex && job.fragment
                         ? job.vertex->input.display_path + " + " + job.fragment->input.display_path
                     : job.vertex ? job.vertex->input.display_path
                                  : job.fragment->input.display_path;
  if (!t.ok && t.refused) {
    outcome.err = fmt::format("{}:{}\n", name, t.error);
    outcome.exit = Exit::Rejected;
    return outcome;
  }
  if (!t.ok) {
    outcome.err = fmt::format(
        "arbiter: internal error: the translation of {} is not valid {} ({}); "
        "nothing was written. This is a bug in arbiter's translator: please report it "
        "with the program.\n",
        name, self_check ? "GLSL 1.10" : "--target " + options.target, t.error);
    outcome.exit = Exit::Environment;
    return outcome;
  }
  // Every output of the job is written, or none (compiler::WriteFilesAtomically), and stdout
  // gets the GLSL only once the files are written.
  Destination d = Place(options, job, several);
  std::vector<compiler::FileToWrite> files;
  if (d.to_stdout) {
    if (!t.vertex.empty() && !t.fragment.empty()) {
      outcome.out = fmt::format("// ---- vertex shader ----\n{}// ---- fragment shader ----\n{}",
                                t.vertex, t.fragment);
    } else {
      outcome.out = t.vertex.empty() ? t.fragment : t.vertex;
    }
  } else {
    if (!t.vertex.empty()) files.push_back({ShaderPath(options, d, several, job, true), t.vertex});
    if (!t.fragment.empty()) {
      files.push_back({ShaderPath(options, d, several, job, false), t.fragment});
    }
  }
  if (!d.bindings.empty()) files.push_back({d.bindings, arbvp::BindingMapToJson(t.bindings)});
  std::string error;
  if (!compiler::WriteFilesAtomically(files, &error)) {
    outcome.err += fmt::format("arbiter: error: {}; nothing was written for {}\n", error, name);
    outcome.exit = Exit::Environment;
    outcome.out.clear();
  }
  return outcome;
}

int RunTranslate(const TranslateCommandOptions& options) {
  arbvp::Mutation mutation;
  if (!arbvp::LookupMutation(options.mutation, &mutation)) {
    fmt::print(stderr, "arbiter: error: unknown mutation '{}'\n", options.mutation);
    return static_cast<int>(Exit::Usage);
  }
  const OutputTarget* target = LookupOutputTarget(options.target);
  if (!target) {
    fmt::print(stderr, "arbiter: error: unknown target '{}' (one of {})\n", options.target,
               OutputTargetNames());
    return static_cast<int>(Exit::Usage);
  }
  if (!options.state.empty() && options.state != "builtins" && options.state != "uniforms") {
    fmt::print(stderr, "arbiter: error: --state takes builtins or uniforms, not '{}'\n",
               options.state);
    return static_cast<int>(Exit::Usage);
  }
  arbvp::EmitOptions probe;
  probe.target = target->dialect;
  if (options.state == "builtins" && arbvp::UsesStateUniforms(probe)) {
    fmt::print(stderr,
               "arbiter: error: --target {} has no built-in GL state: --state builtins is only "
               "for glsl110 and glsl120\n",
               options.target);
    return static_cast<int>(Exit::Usage);
  }
  if (target->kind == OutputKind::Spirv && options.output.empty()) {
    fmt::print(stderr,
               "arbiter: error: --target spirv writes binary modules: give -o FILE or DIR\n");
    return static_cast<int>(Exit::Usage);
  }
  std::vector<LoadedArb> all;
  std::vector<compiler::FileReport> reports;
  Exit exit = LoadArbPrograms(options.common, "translate", &all, &reports);
  PrintLoadReports(reports, options.common);
  if (exit == Exit::Usage) return static_cast<int>(exit);
  // A rejected program is reported and skipped; the others are translated (exit 1 then).
  std::vector<LoadedArb> loaded;
  for (LoadedArb& l : all) {
    if (l.ok()) loaded.push_back(std::move(l));
  }
  const size_t rejected = all.size() - loaded.size();
  if (loaded.empty() || (options.pair && exit != Exit::Ok)) return static_cast<int>(exit);

  std::vector<Job> jobs;
  if (options.pair) {
    Job job;
    int vertices = 0;
    for (const LoadedArb& l : loaded) {
      bool vp = l.checked.program->kind == arbvp::ProgramKind::Vertex;
      vertices += vp ? 1 : 0;
      (vp ? job.vertex : job.fragment) = &l;
    }
    if (loaded.size() != 2 || vertices != 1) {
      fmt::print(stderr,
                 "arbiter: error: --pair takes one vertex program and one fragment program\n");
      return static_cast<int>(Exit::Usage);
    }
    job.stem = Stem(job.vertex->input);
    jobs.push_back(job);
  } else {
    for (const LoadedArb& l : loaded) {
      Job job;
      (l.checked.program->kind == arbvp::ProgramKind::Vertex ? job.vertex : job.fragment) = &l;
      job.stem = Stem(l.input);
      jobs.push_back(job);
    }
  }
  // Several inputs write a directory, even when all but one were rejected.
  const bool several = jobs.size() + rejected > 1;
  if (several && options.output.empty()) {
    fmt::print(stderr,
               "arbiter: error: several programs need -o DIR: one shader per program, not all "
               "of them on stdout\n");
    return static_cast<int>(Exit::Usage);
  }
  for (const std::string* dir : {&options.output, &options.bindings}) {
    if (!several || dir->empty()) continue;
    std::error_code ec;
    fs::create_directories(*dir, ec);
    if (ec) {
      fmt::print(stderr, "arbiter: error: cannot create directory '{}': {}\n", *dir, ec.message());
      return static_cast<int>(Exit::Environment);
    }
  }
  // Two inputs with one stem would overwrite each other's files.
  if (several && !options.output.empty()) {
    std::set<std::string> seen;
    for (const Job& job : jobs) {
      std::string key = job.stem + (job.vertex ? ".vert" : ".frag");
      if (!seen.insert(key).second) {
        fmt::print(stderr, "arbiter: error: two inputs would both write '{}' in '{}'\n", key,
                   options.output);
        return static_cast<int>(Exit::Usage);
      }
    }
  }
  // An output that is an input would replace the program by its translation.
  for (const Job& job : jobs) {
    const Destination d = Place(options, job, several);
    std::vector<std::string> outputs{d.bindings};
    if (!d.to_stdout) {
      if (job.vertex) outputs.push_back(ShaderPath(options, d, several, job, true));
      if (job.fragment) outputs.push_back(ShaderPath(options, d, several, job, false));
    }
    for (const LoadedArb& l : loaded) {
      for (const std::string& out : outputs) {
        std::error_code ec;
        if (!out.empty() && l.input.path != "-" && fs::equivalent(out, l.input.path, ec)) {
          fmt::print(stderr, "arbiter: error: the output '{}' is the input '{}'\n", out,
                     l.input.display_path);
          return static_cast<int>(Exit::Usage);
        }
      }
    }
  }
  // Jobs translate (glslang's self-check) and write their files in parallel; what they
  // print comes out in input order.
  std::vector<Outcome> outcomes(jobs.size());
  ParallelFor(jobs.size(), ResolveJobs(options.common),
              [&](size_t i) { outcomes[i] = RunJob(options, jobs[i], several); });
  for (const Outcome& o : outcomes) {
    std::fputs(o.err.c_str(), stderr);
    std::fwrite(o.out.data(), 1, o.out.size(), stdout);
    exit = Worse(exit, o.exit);
  }
  if (rejected > 0) {
    fmt::print(stderr, "arbiter: {} of {} programs rejected (above); the other {} translated\n",
               rejected, rejected + jobs.size(), jobs.size());
  }
  return static_cast<int>(exit);
}

}  // namespace

// Adds the `translate` subcommand to `app`; the returned function runs it once parsed.
std::function<int()> AddTranslateCommand(CLI::App* app) {
  auto options = std::make_shared<TranslateCommandOptions>();
  CLI::App* cmd =
      app->add_subcommand("translate", "translate ARB programs to GLSL 1.10 (exact semantics)");
  cmd->footer(
      "One input: GLSL to stdout or to -o FILE. Several inputs: -o DIR gets NAME.vert / "
      "NAME.frag per program (and --bindings DIR NAME.vert.bindings.json / "
      "NAME.frag.bindings.json); --target spirv, hlsl and msl add .spv, .hlsl and .metal. --pair "
      "translates a vertex and a fragment program into one GLSL "
      "program with matching varyings (-o BASE writes BASE.vert and BASE.frag). Every "
      "translation is compiled by glslang first; files are written atomically.");
  CommonOptions& common = options->common;
  cmd->add_option("files", common.files, "ARB programs (files, directories, '-')")->required();
  cmd->add_option("-o,--output", options->output, "output file (one program) or directory");
  cmd->add_option("--bindings", options->bindings,
                  "write the binding map (uniforms, attributes, samplers) as JSON to this file "
                  "(or directory, with several programs)");
  cmd->add_flag("--pair", options->pair, "translate a vertex and a fragment program as a pair");
  cmd->add_option("--target", options->target,
                  "output: glsl110 (default), glsl120, glsl330, es100, es300, vk450, spirv, hlsl, "
                  "msl");
  cmd->add_option("--state", options->state,
                  "GL state from GLSL built-ins (builtins, glsl110/glsl120 only) or named uniforms "
                  "(uniforms, forced for the other targets)");
  cmd->add_flag("--no-comments", options->no_comments,
                "do not precede statements with the ARB instruction");
  AddStageOption(cmd, &common.stage, /*glsl=*/false);
  AddLimitsOption(cmd, &common.limits);
  AddColorOption(cmd, &common.color);
  AddErrorLimitOption(cmd, &common.error_limit);
  AddWerrorFlag(cmd, &common.werror);
  AddJobsOption(cmd, &common.jobs, "worker threads");
  // Test-only: inject one translator bug, to prove that `verify` catches it.
  cmd->add_option("--mutation", options->mutation)->group("");
  return [options] { return RunTranslate(*options); };
}

}  // namespace arbiter::cli
