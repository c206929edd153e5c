// VerifyGlsl: per subject (a worker process each, -j at a time), the batches, each engine's
// runs (a nested worker per engine, so that softpipe and llvmpipe each get a process of their
// own), the baseline's runs on perturbed inputs, the probe's three runs (two sentinels, the
// nudged matrices) where engines differ, and the comparison.
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <regex>
#include <set>

#include "arbiter/arbvp/exec_io.h"
#include "arbiter/compiler/diagnostic.h"
#include "arbiter/runtime/glsl_vulkan.h"
#include "arbiter/runtime/mesa.h"
#include "exec/context.h"
#include "glsl_verify/internal.h"
#include "verify/verdict_json.h"

namespace arbiter::runtime {

const std::vector<std::string>& GlslEngineNames() {
  static const std::vector<std::string> kNames = {kGlslEngineSoftpipe, kGlslEngineLlvmpipe,
                                                  kGlslEngineVulkan};
  return kNames;
}

GlslTolerance ToleranceOf(const GlslVerifySubject& subject) {
  // The built-ins GLSL 1.10 gives no precision for beyond GL's "about 1 part in 1e5" per
  // operation, which their implementations (polynomials, exp2 and log2 pairs) exceed.
  static const std::regex kLoose(
      R"(\b(sin|cos|tan|asin|acos|atan|pow|exp|log|exp2|log2|sqrt|inversesqrt|normalize|length|distance|smoothstep|refract|faceforward|reflect|noise[1-4])\s*\()");
  GlslTolerance t;
  for (const compiler::SourceFile* f : {subject.vertex, subject.fragment}) {
    if (f != nullptr && std::regex_search(f->text(), kLoose)) t.loose = true;
  }
  for (const glsl::Reflection* r : {subject.vertex_reflection, subject.fragment_reflection}) {
    if (r != nullptr && !r->samplers.empty()) t.textured = true;
  }
  return t;
}

namespace {

// The largest difference `tolerance` allows between a and b (docs/verify.md): a relative
// bound of the larger of |a|, |b| and the inputs' scale, so that cancellation of large
// inputs into a small result is allowed the error of the inputs.
float AllowedDifference(float a, float b, float scale, const GlslTolerance& tolerance) {
  float relative = tolerance.loose ? 0x1p-10f : 0x1p-14f;
  if (tolerance.textured) relative = std::max(relative, 0x1p-7f);
  return relative * std::max({std::fabs(a), std::fabs(b), scale});
}

}  // namespace

bool WithinTolerance(float a, float b, float scale, const GlslTolerance& tolerance) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  if (std::isinf(a) || std::isinf(b)) return a == b;
  return std::fabs(a - b) <= AllowedDifference(a, b, scale, tolerance);
}

namespace glsl_verify {
namespace {

constexpr float kSentinels[2] = {0.3125f, 0.6875f};
// Perturbed inputs are the inputs each times 1 + or - 2^-17 (GL's "about 1 part in 1e5"
// per operation): by backward error analysis, rounding within the allowed precision is such
// a perturbation of the operands, so an output that moves beyond its tolerance under it is
// within rounding of a discontinuity or too ill-conditioned for any two engines to agree.
constexpr float kPerturbation = 0x1p-17f;

// One engine's runs of a list of inputs, in one worker process.
struct EngineRuns {
  std::vector<GlslRunResult> runs;
  std::string error;
  std::string not_applicable;
};

EngineRuns RunEngine(const std::string& engine, const GlslVerifyOptions& options,
                     const GlslShaders& shaders, const std::vector<GlslExecInputs>& inputs) {
  EngineRuns out;
  auto job = [&](std::string* payload, std::string* job_error) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const GlslExecInputs& in : inputs) {
      GlslRunResult result;
      std::string not_applicable;
      bool ok = false;
      if (engine == kGlslEngineVulkan) {
        ok = RunGlslVulkan(shaders, in, &result, &not_applicable, job_error);
      } else {
        ExecOptions exec;
        exec.backend = options.backend;
        exec.driver = engine;
        ok = RunGlsl(exec, shaders, in, &result, job_error);
      }
      if (!ok && !not_applicable.empty()) {
        *payload = nlohmann::json({{"not_applicable", not_applicable}}).dump();
        return true;
      }
      if (!ok) return false;
      if (!result.usage_error.empty()) {
        *job_error = result.usage_error;
        return false;
      }
      list.push_back(GlslRunResultToJson(result));
    }
    *payload = nlohmann::json({{"runs", list}}).dump();
    return true;
  };
  std::string payload;
  const WorkerStatus status = RunInWorker(options.limits, job, &payload, &out.error);
  if (status != WorkerStatus::Ok) {
    if (out.error.empty()) out.error = "the engine failed";
    return out;
  }
  const nlohmann::json j = nlohmann::json::parse(payload, nullptr, false);
  if (j.is_discarded()) {
    out.error = "the worker's answer is not JSON";
  } else if (j.contains("not_applicable")) {
    out.not_applicable = j["not_applicable"].get<std::string>();
  } else {
    for (const nlohmann::json& r : j["runs"]) {
      GlslRunResult result;
      if (!GlslRunResultFromJson(r, &result)) {
        out.error = "the worker's answer is not a run's result";
        return out;
      }
      out.runs.push_back(std::move(result));
    }
  }
  return out;
}

// The batch with every float input (attributes, varyings, float uniforms, the GL state's
// matrices) perturbed, each number up or down by its own sign of the pattern `pattern`:
// scaling them all alike would hide cancellations.
GlslExecInputs Perturbed(const GlslBatch& batch, uint64_t pattern) {
  uint64_t bits = 0x9e3779b97f4a7c15ull * (pattern + 1);
  auto nudge = [&bits](float* v) {
    bits ^= bits << 13;
    bits ^= bits >> 7;
    bits ^= bits << 17;
    *v *= (bits & 1) != 0 ? 1.0f + kPerturbation : 1.0f - kPerturbation;
  };
  GlslExecInputs in = batch.inputs;
  for (auto& vector : in.vectors) {
    for (auto& [name, values] : vector) {
      // Inputs GL keeps within bounds (the window depth within the depth range, the colours
      // a fragment shader reads within [0, 1]) are not perturbed: beyond them the engines
      // would clip or clamp instead.
      if (name == "gl_FragCoord.z" || name == "gl_Color" || name == "gl_SecondaryColor") {
        continue;
      }
      for (float& v : values) nudge(&v);
    }
  }
  for (size_t u = 0; u < in.uniforms.size(); ++u) {
    if (!batch.float_uniforms[u]) continue;
    for (float& v : in.uniforms[u].second) nudge(&v);
  }
  auto matrix = [&](glm::mat4* m) {
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) nudge(&(*m)[c][r]);
    }
  };
  matrix(&in.state.modelview);
  matrix(&in.state.projection);
  for (glm::mat4& m : in.state.texture) matrix(&m);
  return in;
}

// The largest magnitude among the float inputs of vector `v` (at least 1).
float Scale(const GlslBatch& batch, size_t v) {
  float scale = 1.0f;
  for (const auto& [name, values] : batch.inputs.vectors[v]) {
    for (float x : values) scale = std::max(scale, std::fabs(x));
  }
  for (size_t u = 0; u < batch.inputs.uniforms.size(); ++u) {
    if (!batch.float_uniforms[u]) continue;
    for (float x : batch.inputs.uniforms[u].second) scale = std::max(scale, std::fabs(x));
  }
  return scale;
}

const GlslOutput* Find(const GlslVectorResult& r, const std::string& name,
                       const std::string& stage) {
  for (const GlslOutput& o : r.outputs) {
    if (o.name == name && o.stage == stage) return &o;
  }
  return nullptr;
}

// "gl_Position.y", "m[1].z" (matrices by column), "f".
std::string Label(const GlslOutput& o, size_t c) {
  if (o.value.size() == 1) return o.name;
  const int rows = o.type.rfind("mat", 0) == 0 ? o.type.back() - '0' : 0;
  if (rows > 0 && o.type.size() <= 6) {
    return fmt::format("{}[{}].{}", o.name, c / static_cast<size_t>(rows),
                       "xyzw"[c % static_cast<size_t>(rows)]);
  }
  if (o.value.size() <= 4) return fmt::format("{}.{}", o.name, "xyzw"[c]);
  return fmt::format("{}[{}]", o.name, c);
}

// The inputs of vector `v`: each read slot and every uniform, "gl_Vertex = (1, 2, 3, 1)".
std::vector<std::string> DescribeInputs(const GlslBatch& batch, size_t v) {
  auto values = [](const std::vector<float>& xs) {
    std::vector<std::string> s;
    for (float x : xs) s.push_back(arbvp::FormatFloat(x));
    return s.size() == 1 ? s[0] : fmt::format("({})", fmt::join(s, ", "));
  };
  std::vector<std::string> out;
  for (const GlslInputSlot& slot : batch.inputs.slots) {
    if (!slot.read) continue;
    auto it = batch.inputs.vectors[v].find(slot.name);
    if (it != batch.inputs.vectors[v].end()) {
      out.push_back(fmt::format("{} = {}", slot.name, values(it->second)));
    }
  }
  for (const auto& [name, xs] : batch.inputs.uniforms) {
    out.push_back(fmt::format("uniform {} = {}", name, values(xs)));
  }
  for (const auto& [unit, texture] : batch.inputs.textures) {
    out.push_back(fmt::format("texture unit {} = {}", unit, arbvp::DescribeTexture(texture)));
  }
  return out;
}

// The probe's findings for every batch and vector, and the components a path leaves
// unwritten ("name|stage|c").
struct ProbeResults {
  bool ran = false;
  std::vector<std::vector<ProbeFinding>> findings;            // [batch][vector]
  std::vector<std::vector<std::set<std::string>>> unwritten;  // [batch][vector]
  // Components that move beyond their tolerance when the state matrices are nudged apart.
  std::vector<std::vector<std::set<std::string>>> nudged;  // [batch][vector]
};

std::string Key(const std::string& name, const std::string& stage, size_t c) {
  return fmt::format("{}|{}|{}", name, stage, c);
}

ProbeResults RunProbe(const GlslVerifySubject& subject, const Probe& probe,
                      const std::vector<GlslBatch>& batches, const GlslVerifyOptions& options,
                      const GlslTolerance& tolerance, std::string* why) {
  ProbeResults out;
  // The probe's shaders, reflected as exec needs them.
  compiler::DiagnosticSink sink(0);
  std::unique_ptr<compiler::SourceFile> files[2];
  glsl::Reflection reflections[2];
  GlslShaders shaders;
  const std::string* texts[2] = {&probe.vertex, &probe.fragment};
  const compiler::SourceFile* originals[2] = {subject.vertex, subject.fragment};
  for (int s = 0; s < 2; ++s) {
    if (originals[s] == nullptr) continue;
    files[s] = std::make_unique<compiler::SourceFile>(originals[s]->path(), *texts[s]);
    reflections[s] = glsl::ReflectShader(s == 0 ? glsl::Stage::Vertex : glsl::Stage::Fragment,
                                         {files[s].get()}, &sink);
    if (!reflections[s].ok) {
      *why = "the instrumented shader does not compile";
      return out;
    }
  }
  if (files[0]) {
    shaders.vertex = probe.vertex;
    shaders.vertex_reflection = &reflections[0];
  }
  if (files[1]) {
    shaders.fragment = probe.fragment;
    shaders.fragment_reflection = &reflections[1];
  }
  // Three runs of each batch: the two sentinels, then the first with the matrices nudged.
  std::vector<GlslExecInputs> inputs;
  for (int run = 0; run < 3; ++run) {
    for (const GlslBatch& b : batches) {
      GlslExecInputs in = b.inputs;
      in.uniforms.emplace_back(kSentinelUniform, std::vector<float>{kSentinels[run == 1]});
      std::vector<float> nudge4(16, 1.0f);
      std::vector<float> nudge3(9, 1.0f);
      if (run == 2) {
        for (size_t k = 0; k < 16; ++k)
          nudge4[k] += (k * 7 % 3 == 0 ? 1.0f : -1.0f) * kPerturbation;
        for (size_t k = 0; k < 9; ++k) nudge3[k] += (k * 5 % 3 == 0 ? -1.0f : 1.0f) * kPerturbation;
      }
      in.uniforms.emplace_back(kNudge4Uniform, std::move(nudge4));
      in.uniforms.emplace_back(kNudge3Uniform, std::move(nudge3));
      for (const char* u : {kSentinelUniform, kNudge4Uniform, kNudge3Uniform}) {
        in.declared_uniforms.emplace_back(u);
      }
      inputs.push_back(std::move(in));
    }
  }
  // The probe runs on Mesa's GLSL compiler (it needs a GL engine's outputs): the first GL
  // engine asked for, else softpipe.
  std::string engine = kGlslEngineSoftpipe;
  for (const std::string& e : options.engines) {
    if (e != kGlslEngineVulkan) {
      engine = e;
      break;
    }
  }
  EngineRuns runs = RunEngine(engine, options, shaders, inputs);
  if (!runs.error.empty() || runs.runs.size() != inputs.size()) {
    *why = "the instrumented shader did not run: " + runs.error;
    return out;
  }
  const size_t n = batches.size();
  out.ran = true;
  out.findings.resize(n);
  out.unwritten.resize(n);
  out.nudged.resize(n);
  for (size_t b = 0; b < n; ++b) {
    const auto& first = runs.runs[b].vectors;
    const auto& second = runs.runs[n + b].vectors;
    const auto& nudged = runs.runs[2 * n + b].vectors;
    out.findings[b].resize(first.size());
    out.unwritten[b].resize(first.size());
    out.nudged[b].resize(first.size());
    for (size_t v = 0; v < first.size() && v < second.size(); ++v) {
      out.findings[b][v] = ReadProbe(first[v]);
      if (first[v].discarded || second[v].discarded) continue;
      for (const GlslOutput& o : first[v].outputs) {
        const GlslOutput* q = v < nudged.size() ? Find(nudged[v], o.name, o.stage) : nullptr;
        for (size_t c = 0; q != nullptr && c < o.value.size() && c < q->value.size(); ++c) {
          if (!WithinTolerance(o.value[c], q->value[c], Scale(batches[b], v), tolerance)) {
            out.nudged[b][v].insert(Key(o.name, o.stage, c));
          }
        }
        const GlslOutput* p = Find(second[v], o.name, o.stage);
        if (p == nullptr) continue;
        for (size_t c = 0; c < o.value.size() && c < p->value.size(); ++c) {
          if (std::bit_cast<uint32_t>(o.value[c]) != std::bit_cast<uint32_t>(p->value[c])) {
            out.unwritten[b][v].insert(Key(o.name, o.stage, c));
          }
        }
      }
    }
  }
  return out;
}

constexpr const char* kUnwritten =
    "a value this path never wrote: an output left unwritten or a variable read before it is "
    "written (GLSL 1.10 sections 4.1 and 7.1: undefined)";

// Why a disagreement at (b, v, output, component) is not one: "" when it is.
struct Excuse {
  std::string undefined;
  bool unstable = false;
};

class Comparer {
 public:
  Comparer(const Probe& probe, const ProbeResults& probe_results,
           const std::map<std::string, std::string>& renamed, Verdict* verdict)
      : probe_(probe), probe_results_(probe_results), renamed_(renamed), verdict_(verdict) {}

  Excuse ExcuseFor(size_t b, size_t v, const std::string& name, const std::string& stage, size_t c,
                   bool unstable) const {
    Excuse e;
    if (!probe_.static_causes.empty()) {
      e.undefined = fmt::format("{}", fmt::join(probe_.static_causes, "; "));
      return e;
    }
    if (probe_results_.ran && b < probe_results_.findings.size() &&
        v < probe_results_.findings[b].size()) {
      auto it = renamed_.find(name);
      const std::string probe_name = it != renamed_.end() ? it->second : name;
      if (!name.empty() && probe_results_.unwritten[b][v].count(Key(probe_name, stage, c))) {
        e.undefined = kUnwritten;
        return e;
      }
      const ProbeFinding& f = probe_results_.findings[b][v];
      if (f.kinds != 0) {
        e.undefined = DescribeFinding(f, probe_);
        return e;
      }
      if (!name.empty() && probe_results_.nudged[b][v].count(Key(probe_name, stage, c)) > 0) {
        unstable = true;
      }
    }
    e.unstable = unstable;
    return e;
  }

  // Counts or records one candidate disagreement.
  void Candidate(const Excuse& e, Disagreement d) {
    if (!e.undefined.empty()) {
      verdict_->undefined[e.undefined] += 1;
    } else if (e.unstable) {
      verdict_->unstable += 1;
    } else {
      verdict_->disagreements.push_back(std::move(d));
    }
  }

 private:
  const Probe& probe_;
  const ProbeResults& probe_results_;
  const std::map<std::string, std::string>& renamed_;
  Verdict* verdict_;
};

Verdict VerifyOne(const GlslVerifySubject& subject, const GlslVerifyOptions& options) {
  Verdict verdict;
  verdict.name = subject.name;
  std::string error;
  const std::vector<GlslBatch> batches = GenerateGlslInputs(subject, options.generate, &error);
  if (batches.empty()) {
    // EXT_gpu_shader4's integer samplers, texture arrays: no engine is wrong, verify has no
    // texture of that kind to give.
    verdict.not_applicable["the input generator"] = error;
    return verdict;
  }
  for (const GlslBatch& b : batches) verdict.vectors += b.inputs.vectors.size();
  GlslShaders shaders;
  if (subject.vertex != nullptr) {
    shaders.vertex = subject.vertex->text();
    shaders.vertex_reflection = subject.vertex_reflection;
  }
  if (subject.fragment != nullptr) {
    shaders.fragment = subject.fragment->text();
    shaders.fragment_reflection = subject.fragment_reflection;
  }
  std::vector<GlslExecInputs> plain;
  for (const GlslBatch& b : batches) plain.push_back(b.inputs);
  // Each engine's runs; the baseline's also on the perturbed inputs.
  std::map<std::string, EngineRuns> runs;
  std::vector<std::string> ran;  // engines with results, baseline first
  std::vector<std::string> errors;
  for (size_t e = 0; e < options.engines.size(); ++e) {
    const std::string& engine = options.engines[e];
    std::vector<GlslExecInputs> inputs = plain;
    if (ran.empty()) {
      for (uint64_t pattern : {1u, 2u}) {
        for (const GlslBatch& b : batches) inputs.push_back(Perturbed(b, pattern));
      }
    }
    EngineRuns r = RunEngine(engine, options, shaders, inputs);
    if (!r.not_applicable.empty()) {
      verdict.not_applicable[engine] = r.not_applicable;
      continue;
    }
    // Mesa's compiler rejecting what arbiter accepts is a finding of the checker's (check
    // reports it), not a failure of the run.
    if (r.error.rfind("mesa rejected", 0) == 0 || r.error.rfind("mesa cannot link", 0) == 0) {
      verdict.not_applicable[engine] = r.error;
      continue;
    }
    if (!r.error.empty() || r.runs.size() != inputs.size()) {
      errors.push_back(fmt::format("{}: {}", engine, r.error.empty() ? "no result" : r.error));
      continue;
    }
    for (size_t b = 0; b < batches.size(); ++b) {
      if (options.tamper) options.tamper(engine, b, &r.runs[b].vectors);
    }
    ran.push_back(engine);
    runs[engine] = std::move(r);
  }
  for (size_t i = 0; i < errors.size(); ++i) verdict.error += (i ? "; " : "") + errors[i];
  if (ran.size() < 2) return verdict;

  // The probe, only when some engines differ beyond tolerance: most shaders need none.
  const GlslTolerance tolerance = ToleranceOf(subject);
  const std::string& base = ran[0];
  const size_t n = batches.size();
  bool any_difference = false;
  for (size_t e = 1; e < ran.size() && !any_difference; ++e) {
    for (size_t b = 0; b < n && !any_difference; ++b) {
      const auto& r0 = runs[base].runs[b].vectors;
      const auto& r1 = runs[ran[e]].runs[b].vectors;
      for (size_t v = 0; v < r0.size() && v < r1.size() && !any_difference; ++v) {
        if (r0[v].discarded != r1[v].discarded) any_difference = true;
        for (const GlslOutput& o : r0[v].outputs) {
          const GlslOutput* p = Find(r1[v], o.name, o.stage);
          if (p == nullptr || p->value.size() != o.value.size()) {
            any_difference = true;
            break;
          }
          for (size_t c = 0; c < o.value.size(); ++c) {
            if (!WithinTolerance(o.value[c], p->value[c], Scale(batches[b], v), tolerance)) {
              any_difference = true;
            }
          }
        }
      }
    }
  }
  Probe probe;
  ProbeResults probe_results;
  if (any_difference) {
    probe = MakeProbe(subject);
    std::string why = probe.why;
    if (probe.ok) probe_results = RunProbe(subject, probe, batches, options, tolerance, &why);
    if (!probe_results.ran) verdict.not_applicable[kGlslProbeName] = why;
  }
  Comparer comparer(probe, probe_results, probe.renamed, &verdict);

  // Whether the baseline's own result moves under perturbation (a discontinuity): its
  // discard, or (`o` non-null) component c of output `o`.
  auto unstable = [&](size_t b, size_t v, const GlslOutput* o, size_t c) {
    const GlslVectorResult& at = runs[base].runs[b].vectors[v];
    for (size_t k = 1; k <= 2; ++k) {
      const auto& pr = runs[base].runs[k * n + b].vectors;
      if (v >= pr.size() || pr[v].discarded != at.discarded) return true;
      if (o == nullptr || at.discarded) continue;
      const GlslOutput* p = Find(pr[v], o->name, o->stage);
      if (p == nullptr || c >= p->value.size()) return true;
      if (!WithinTolerance(o->value[c], p->value[c], Scale(batches[b], v), tolerance)) {
        return true;
      }
    }
    return false;
  };

  for (size_t e = 1; e < ran.size(); ++e) {
    const std::string& engine = ran[e];
    for (size_t b = 0; b < n; ++b) {
      const auto& r0 = runs[base].runs[b].vectors;
      const auto& r1 = runs[engine].runs[b].vectors;
      for (size_t v = 0; v < r0.size() && v < r1.size(); ++v) {
        Disagreement d;
        d.batch = batches[b].name;
        d.vector = v;
        d.engines = {engine};
        d.inputs = DescribeInputs(batches[b], v);
        if (r0[v].discarded != r1[v].discarded) {
          d.what = fmt::format("discarded by {} only", r0[v].discarded ? base : engine);
          comparer.Candidate(comparer.ExcuseFor(b, v, "", "", 0, unstable(b, v, nullptr, 0)), d);
          continue;
        }
        if (r0[v].discarded) continue;
        const float scale = Scale(batches[b], v);
        for (const GlslOutput& o : r0[v].outputs) {
          const GlslOutput* p = Find(r1[v], o.name, o.stage);
          d.reg = o.name;
          if (p == nullptr || p->value.size() != o.value.size()) {
            d.what = fmt::format("not written by {}", engine);
            d.component = -1;
            comparer.Candidate(Excuse{}, d);
            continue;
          }
          for (size_t c = 0; c < o.value.size(); ++c) {
            verdict.compared += 1;
            if (WithinTolerance(o.value[c], p->value[c], scale, tolerance)) continue;
            d.component = static_cast<int>(c);
            d.label = Label(o, c);
            d.what.clear();
            d.tolerance = AllowedDifference(o.value[c], p->value[c], scale, tolerance);
            d.values = {{base, o.value[c]}, {engine, p->value[c]}};
            for (const std::string& other : ran) {
              if (other == base || other == engine) continue;
              const auto& ro = runs[other].runs[b].vectors;
              const GlslOutput* q = v < ro.size() ? Find(ro[v], o.name, o.stage) : nullptr;
              if (q != nullptr && c < q->value.size()) d.values[other] = q->value[c];
            }
            comparer.Candidate(comparer.ExcuseFor(b, v, o.name, o.stage, c, unstable(b, v, &o, c)),
                               d);
          }
        }
      }
    }
  }
  return verdict;
}

}  // namespace
}  // namespace glsl_verify

std::vector<Verdict> VerifyGlsl(const std::vector<GlslVerifySubject>& subjects,
                                const GlslVerifyOptions& options) {
  std::vector<Verdict> verdicts(subjects.size());
  if (subjects.empty()) return verdicts;
  if (options.backend == Backend::OSMesa) exec::PreloadOsMesa();
  WorkerLimits outer = options.limits;
  // A subject's worker waits for its engines' workers (each within its own limit).
  outer.timeout_ms = options.limits.timeout_ms * static_cast<int>(options.engines.size() + 2);
  std::vector<WorkerResult> results;
  RunInWorkers(
      outer, subjects.size(), static_cast<size_t>(std::max(1, options.jobs)),
      [&](size_t i) -> WorkerJob {
        return [&, i](std::string* payload, std::string* /*error*/) {
          *payload = VerdictToJson(glsl_verify::VerifyOne(subjects[i], options)).dump();
          return true;
        };
      },
      &results);
  for (size_t i = 0; i < subjects.size(); ++i) {
    Verdict& v = verdicts[i];
    const nlohmann::json j = results[i].status == WorkerStatus::Ok
                                 ? nlohmann::json::parse(results[i].payload, nullptr, false)
                                 : nlohmann::json();
    if (results[i].status != WorkerStatus::Ok || j.is_discarded() || !VerdictFromJson(j, &v)) {
      v = Verdict{};
      v.name = subjects[i].name;
      v.error = results[i].error.empty() ? "the verify worker failed" : results[i].error;
    }
  }
  return verdicts;
}

}  // namespace arbiter::runtime
