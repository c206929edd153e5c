// arbiter verify's engine: programs go to worker processes in chunks, -j at a time; a worker
// makes one GL context and, per program, generates the inputs, runs the interpreter and both
// Mesa engines and compares them (compare.cpp); only the verdicts come back.
#include "arbiter/runtime/verify.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <nlohmann/json.hpp>

#include "arbiter/arbvp/deviations.h"
#include "arbiter/arbvp/exec_io.h"
#include "arbiter/arbvp/interpret.h"
#include "arbiter/runtime/translate.h"
#include "exec/context.h"
#include "exec_glsl/target_run.h"
#include "verify/verdict_json.h"
#include "worker/chunks.h"

namespace arbiter::runtime {
namespace {

struct Prepared {
  std::vector<arbvp::InputBatch> batches;
  std::vector<std::vector<arbvp::VectorResult>> ref;  // per batch
};

// Mesa has never implemented the NV program options: such a program is verified against its
// translation only.
bool UsesNvOptions(const VerifySubject& subject) {
  return (subject.vertex && subject.vertex->Nv()) || (subject.fragment && subject.fragment->Nv());
}

Prepared Prepare(const VerifySubject& subject, const VerifyOptions& options) {
  Prepared p;
  p.batches = arbvp::GenerateInputs(subject.vertex, subject.fragment, options.generate);
  for (const arbvp::InputBatch& batch : p.batches) {
    if (subject.vertex && subject.fragment) {
      p.ref.push_back(arbvp::InterpretPair(*subject.vertex, *subject.fragment, batch.inputs,
                                           subject.vertex_source, subject.fragment_source));
    } else if (subject.vertex) {
      p.ref.push_back(arbvp::Interpret(*subject.vertex, batch.inputs, subject.vertex_source));
    } else {
      p.ref.push_back(arbvp::Interpret(*subject.fragment, batch.inputs, subject.fragment_source));
    }
  }
  return p;
}

// Counts the components the interpreter leaves out whatever the engine.
void CountUntestable(const Prepared& p, Verdict* verdict) {
  for (const auto& batch : p.ref) {
    verdict->vectors += batch.size();
    for (const arbvp::VectorResult& r : batch) {
      if (!r.kill_undefined.empty()) verdict->undefined[r.kill_undefined] += 1;
      if (r.kill_unstable) verdict->unstable += 1;
      for (const arbvp::OutputRegister& o : r.outputs) {
        for (size_t c = 0; c < 4; ++c) {
          if (!(o.written & (1u << c))) continue;
          if (!o.undefined[c].empty()) {
            verdict->undefined[o.undefined[c]] += 1;
          } else if (std::isinf(o.tolerance[c]) && !r.kill_unstable) {
            verdict->unstable += 1;
          }
        }
      }
    }
  }
}

// The value of `d`'s component in one engine's results, if it has one.
bool ValueAt(const std::vector<arbvp::VectorResult>& results, const Disagreement& d, float* out) {
  if (d.vector >= results.size() || d.component < 0) return false;
  for (const arbvp::OutputRegister& o : results[d.vector].outputs) {
    if (o.name == d.reg && (o.written & (1u << d.component))) {
      *out = o.value[static_cast<size_t>(d.component)];
      return true;
    }
  }
  return false;
}

std::vector<std::string> MesaEngines(const VerifyOptions& options, const VerifySubject& subject) {
  std::vector<std::string> engines;
  if (options.mesa_arb && !UsesNvOptions(subject)) engines.emplace_back(kEngineMesaArb);
  if (options.mesa_glsl) engines.emplace_back(kEngineMesaGlsl);
  for (const TargetEngineInfo& t : kTargetEngines) {
    if (std::find(options.targets.begin(), options.targets.end(), t.name) !=
        options.targets.end()) {
      engines.emplace_back(t.name);
    }
  }
  return engines;
}

// The engines of one worker: the compatibility context of mesa-arb and mesa-glsl, and one
// context per target engine.
struct Engines {
  std::unique_ptr<ArbExecutor> executor;
  std::map<std::string, std::unique_ptr<TargetEngine>> targets;
};

// The deviations of a target engine are mesa-glsl's (the same compiler runs the same
// GLSL); on the ES engines also llvmpipe-cube-edge on every driver: OpenGL ES 3.0 filters
// cube maps seamlessly (ES 3.0 section 3.8.9.1), across the face edges that GL 2.0 and the
// interpreter clamp at. vulkan-spirv runs on lavapipe, llvmpipe's compiler, whatever the
// driver option says (and Vulkan's cube maps are seamless too: llvmpipe-cube-edge). On
// softpipe the GL target engines' points are back-facing (softpipe-point-facing).
uint32_t Deviations(const std::string& engine, const VerifyOptions& options) {
  const bool target = engine != kEngineMesaArb && engine != kEngineMesaGlsl;
  const std::string driver = engine == kEngineVulkanSpirv ? "llvmpipe" : options.exec.driver;
  uint32_t mask = arbvp::ApplicableDeviations(target ? kEngineMesaGlsl : engine, driver);
  if (engine == kEngineMesaEs300 || engine == kEngineMesaEs100) {
    for (const arbvp::DeviationInfo& d : arbvp::KnownDeviations()) {
      if (d.name == "llvmpipe-cube-edge") mask |= static_cast<uint32_t>(d.bit);
    }
  }
  // softpipe draws the points of a core or ES context as sprites it calls back-facing.
  if (target && engine != kEngineVulkanSpirv && driver == "softpipe") {
    mask |= arbvp::kDevPointFacingSoftpipe;
  }
  return mask;
}

std::string MesaError(const VerifyOptions& options, const std::string& error) {
  return fmt::format("mesa ({}, {}): {}", BackendName(options.exec.backend), options.exec.driver,
                     error);
}

// One subject's verdict: the interpreter and the Mesa engines on every batch, compared.
Verdict VerifyOne(Engines* engines, const VerifySubject& subject, const VerifyOptions& options) {
  Verdict verdict;
  verdict.name = subject.name;
  const Prepared p = Prepare(subject, options);
  CountUntestable(p, &verdict);
  const ArbPrograms programs{subject.vertex, subject.fragment};
  // Per engine, its results per batch (all batches, or none when it failed).
  std::map<std::string, std::vector<std::vector<arbvp::VectorResult>>> runs;
  std::vector<std::string> errors;
  for (const std::string& engine : MesaEngines(options, subject)) {
    std::vector<std::vector<arbvp::VectorResult>> batches;
    std::string error;
    std::string not_applicable;
    ArbExecutor* executor = engines->executor.get();
    auto target = engines->targets.find(engine);
    if (engine == kEngineMesaGlsl) {
      // A program GLSL 1.10 cannot express (PK*/UP*: no bit casts) has no mesa-glsl run, as
      // a target engine has none for what its target refuses.
      const CheckedTranslation t = EmitTranslation(subject.vertex, subject.fragment, options.emit,
                                                   subject.vertex_source, subject.fragment_source);
      if (t.refused) {
        verdict.not_applicable[engine] = t.error;
        continue;
      }
    }
    for (const arbvp::InputBatch& batch : p.batches) {
      std::vector<arbvp::VectorResult> results;
      bool ok = false;
      if (target != engines->targets.end()) {
        ok = target->second->Run(programs, options.emit, batch.inputs, &results, &not_applicable,
                                 &error, subject.vertex_source, subject.fragment_source);
      } else if (engine == kEngineMesaArb) {
        ok = executor->Run(programs, batch.inputs, &results, &error);
      } else {
        ok = executor->RunTranslated(programs, options.emit, batch.inputs, &results, &error);
      }
      if (!ok) break;
      batches.push_back(std::move(results));
    }
    if (!not_applicable.empty()) {
      verdict.not_applicable[engine] = not_applicable;
      continue;
    }
    if (!error.empty()) {
      errors.push_back(engine + ": " + error);
      continue;
    }
    const uint32_t applicable = Deviations(engine, options);
    for (size_t b = 0; b < batches.size() && b < p.ref.size(); ++b) {
      CompareWithReference(p.ref[b], batches[b], engine, applicable, p.batches[b].name, &verdict);
    }
    runs[engine] = std::move(batches);
  }
  // Each disagreement with every engine's value and the inputs its vector read.
  for (Disagreement& d : verdict.disagreements) {
    size_t b = 0;
    while (b < p.batches.size() && p.batches[b].name != d.batch) ++b;
    if (b == p.batches.size()) continue;
    float value = 0.0f;
    if (ValueAt(p.ref[b], d, &value)) d.values[kEngineRef] = value;
    for (const auto& [engine, batches] : runs) {
      if (b < batches.size() && ValueAt(batches[b], d, &value)) d.values[engine] = value;
    }
    d.inputs =
        arbvp::DescribeReadInputs(subject.vertex, subject.fragment, p.batches[b].inputs, d.vector);
  }
  for (size_t i = 0; i < errors.size(); ++i) verdict.error += (i ? "; " : "") + errors[i];
  return verdict;
}

// The job of subjects [first, first + count): one GL context, their verdicts as a JSON array.
WorkerJob ChunkJob(const std::vector<VerifySubject>& subjects, size_t first, size_t count,
                   const VerifyOptions& options) {
  return [&subjects, first, count, &options](std::string* payload, std::string* job_error) {
    Engines engines;
    if (options.mesa_arb || options.mesa_glsl) {
      engines.executor = CreateArbExecutor(options.exec, job_error);
      if (!engines.executor) return false;
    }
    for (const TargetEngineInfo& t : kTargetEngines) {
      if (std::find(options.targets.begin(), options.targets.end(), t.name) ==
          options.targets.end()) {
        continue;
      }
      std::string error;
      std::unique_ptr<TargetEngine> engine =
          CreateTargetEngine(t.target, options.exec.driver, &error);
      if (!engine) {
        *job_error = fmt::format("{}: {}", t.name, error);
        return false;
      }
      engines.targets[t.name] = std::move(engine);
    }
    nlohmann::json out = nlohmann::json::array();
    for (size_t i = first; i < first + count; ++i) {
      out.push_back(VerdictToJson(VerifyOne(&engines, subjects[i], options)));
    }
    *payload = out.dump();
    // The worker exits right after its job: the system frees the contexts faster than
    // destroying them does (unmapping softpipe's buffers page by page).
    (void)engines.executor.release();
    for (auto& [name, engine] : engines.targets) (void)engine.release();
    return true;
  };
}

}  // namespace

std::vector<Verdict> Verify(const std::vector<VerifySubject>& subjects,
                            const VerifyOptions& options) {
  std::vector<Verdict> verdicts(subjects.size());
  if (subjects.empty()) return verdicts;
  if (options.exec.backend == Backend::OSMesa) exec::PreloadOsMesa();
  ChunkedBatch batch;
  batch.items = subjects.size();
  batch.workers = static_cast<size_t>(std::max(1, options.jobs));
  // Two chunks per worker: each pays a GL context (a fifth of the work of a 50-program
  // chunk on softpipe), and programs cost about the same.
  batch.per_worker = 2;
  batch.largest = 256;
  batch.limits = options.limits;
  batch.make_job = [&](size_t first, size_t count) {
    return ChunkJob(subjects, first, count, options);
  };
  batch.read = [&](size_t i, const nlohmann::json& entry) {
    return VerdictFromJson(entry, &verdicts[i]);
  };
  batch.failed = [&](size_t i, const std::string& error, bool /*environment*/) {
    // The interpreter's share of the verdict, which needs no driver.
    Verdict& verdict = verdicts[i];
    verdict = Verdict{};
    verdict.name = subjects[i].name;
    CountUntestable(Prepare(subjects[i], options), &verdict);
    verdict.error = MesaError(options, error);
  };
  RunChunked(batch);
  return verdicts;
}

}  // namespace arbiter::runtime
