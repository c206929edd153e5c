// arbiter verify's engine: inputs from the generator, the interpreter in process, both Mesa
// engines in one worker, then the comparison (compare.cpp).
#include "arbiter/runtime/verify.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <nlohmann/json.hpp>

#include "arbiter/arbvp/deviations.h"
#include "arbiter/arbvp/exec_io.h"
#include "arbiter/arbvp/interpret.h"

namespace arbiter::runtime {
namespace {

struct Prepared {
  std::vector<arbvp::InputBatch> batches;
  std::vector<std::vector<arbvp::VectorResult>> ref;  // per batch
};

// What Mesa gave for one subject: per engine, results per batch, or an error.
struct MesaRuns {
  std::map<std::string, std::vector<std::vector<arbvp::VectorResult>>> results;
  std::map<std::string, std::string> errors;
};

std::vector<std::string> MesaEngines(const VerifyOptions& options) {
  std::vector<std::string> engines;
  if (options.mesa_arb) engines.emplace_back(kEngineMesaArb);
  if (options.mesa_glsl) engines.emplace_back(kEngineMesaGlsl);
  return engines;
}

// Runs the Mesa engines of `subjects` (indices `which`) on one context; in JSON, one entry
// per subject: {"mesa-arb": [batch results...] or {"error": ...}, "mesa-glsl": ...}.
bool RunMesa(ArbExecutor* executor, const std::vector<VerifySubject>& subjects,
             const std::vector<Prepared>& prepared, const std::vector<size_t>& which,
             const VerifyOptions& options, nlohmann::ordered_json* out) {
  *out = nlohmann::ordered_json::array();
  for (size_t s : which) {
    const VerifySubject& subject = subjects[s];
    ArbPrograms programs{subject.vertex, subject.fragment};
    nlohmann::ordered_json entry = nlohmann::ordered_json::object();
    for (const std::string& engine : MesaEngines(options)) {
      nlohmann::ordered_json batches = nlohmann::ordered_json::array();
      std::string error;
      for (const arbvp::InputBatch& batch : prepared[s].batches) {
        std::vector<arbvp::VectorResult> results;
        bool ok =
            engine == kEngineMesaArb
                ? executor->Run(programs, batch.inputs, &results, &error)
                : executor->RunTranslated(programs, options.emit, batch.inputs, &results, &error);
        if (!ok) break;
        batches.push_back(arbvp::ResultsToJson(results, /*with_bindings=*/true));
      }
      if (!error.empty()) {
        entry[engine] = nlohmann::ordered_json{{"error", error}};
      } else {
        entry[engine] = std::move(batches);
      }
    }
    out->push_back(std::move(entry));
  }
  return true;
}

// Reads RunMesa's JSON for one subject.
bool ReadMesa(const nlohmann::json& entry, MesaRuns* runs, std::string* error) {
  for (const auto& [engine, value] : entry.items()) {
    if (value.is_object()) {
      runs->errors[engine] = value.value("error", std::string("no result"));
      continue;
    }
    auto& batches = runs->results[engine];
    for (const nlohmann::json& batch : value) {
      batches.emplace_back();
      if (!arbvp::ResultsFromJson(batch, &batches.back(), error)) return false;
    }
  }
  return true;
}

// Runs RunMesa for `which` in a worker; fills `runs` (indexed like `subjects`).
WorkerStatus RunMesaInWorker(const std::vector<VerifySubject>& subjects,
                             const std::vector<Prepared>& prepared,
                             const std::vector<size_t>& which, const VerifyOptions& options,
                             std::vector<MesaRuns>* runs, std::string* error) {
  auto job = [&](std::string* payload, std::string* job_error) {
    std::unique_ptr<ArbExecutor> executor = CreateArbExecutor(options.exec, job_error);
    if (!executor) return false;
    nlohmann::ordered_json out;
    if (!RunMesa(executor.get(), subjects, prepared, which, options, &out)) return false;
    *payload = out.dump();
    return true;
  };
  // The time limit is per program.
  WorkerLimits limits = options.limits;
  const int64_t total =
      static_cast<int64_t>(limits.timeout_ms) * static_cast<int64_t>(which.size());
  limits.timeout_ms = static_cast<int>(std::min<int64_t>(total, 24 * 3600 * 1000));
  std::string payload;
  WorkerStatus status = RunInWorker(limits, job, &payload, error);
  if (status != WorkerStatus::Ok) return status;
  nlohmann::json json = nlohmann::json::parse(payload, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded() || !json.is_array() || json.size() != which.size()) {
    *error = "the worker's answer is not the expected JSON";
    return WorkerStatus::Crashed;
  }
  for (size_t i = 0; i < which.size(); ++i) {
    if (!ReadMesa(json[i], &(*runs)[which[i]], error)) return WorkerStatus::Crashed;
  }
  return WorkerStatus::Ok;
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

}  // namespace

std::vector<Verdict> Verify(const std::vector<VerifySubject>& subjects,
                            const VerifyOptions& options) {
  std::vector<Prepared> prepared;
  prepared.reserve(subjects.size());
  for (const VerifySubject& s : subjects) prepared.push_back(Prepare(s, options));

  std::vector<MesaRuns> runs(subjects.size());
  std::vector<std::string> failures(subjects.size());
  if (!MesaEngines(options).empty() && !subjects.empty()) {
    std::vector<size_t> all(subjects.size());
    for (size_t i = 0; i < all.size(); ++i) all[i] = i;
    std::string error;
    if (RunMesaInWorker(subjects, prepared, all, options, &runs, &error) != WorkerStatus::Ok) {
      // Isolate the subject that brought the worker down: each alone.
      for (size_t i = 0; i < subjects.size(); ++i) {
        runs[i] = MesaRuns{};
        if (RunMesaInWorker(subjects, prepared, {i}, options, &runs, &error) != WorkerStatus::Ok) {
          failures[i] = fmt::format("mesa ({}, {}): {}", BackendName(options.exec.backend),
                                    options.exec.driver, error);
        }
      }
    }
  }

  std::vector<Verdict> verdicts;
  for (size_t s = 0; s < subjects.size(); ++s) {
    Verdict verdict;
    verdict.name = subjects[s].name;
    const Prepared& p = prepared[s];
    CountUntestable(p, &verdict);
    std::vector<std::string> errors;
    if (!failures[s].empty()) errors.push_back(failures[s]);
    for (const auto& [engine, error] : runs[s].errors) errors.push_back(engine + ": " + error);
    for (const auto& [engine, batches] : runs[s].results) {
      uint32_t applicable = arbvp::ApplicableDeviations(engine, options.exec.driver);
      for (size_t b = 0; b < batches.size() && b < p.ref.size(); ++b) {
        CompareWithReference(p.ref[b], batches[b], engine, applicable, p.batches[b].name, &verdict);
      }
    }
    for (Disagreement& d : verdict.disagreements) {
      size_t b = 0;
      while (b < p.batches.size() && p.batches[b].name != d.batch) ++b;
      if (b == p.batches.size()) continue;
      float value = 0.0f;
      if (ValueAt(p.ref[b], d, &value)) d.values[kEngineRef] = value;
      for (const auto& [engine, batches] : runs[s].results) {
        if (b < batches.size() && ValueAt(batches[b], d, &value)) d.values[engine] = value;
      }
      d.inputs = arbvp::DescribeReadInputs(subjects[s].vertex, subjects[s].fragment,
                                           p.batches[b].inputs, d.vector);
    }
    for (size_t i = 0; i < errors.size(); ++i) {
      verdict.error += (i ? "; " : "") + errors[i];
    }
    verdicts.push_back(std::move(verdict));
  }
  return verdicts;
}

}  // namespace arbiter::runtime
