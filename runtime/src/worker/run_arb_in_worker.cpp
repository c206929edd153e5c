// RunArbInWorker: the Mesa executor in a worker process; results travel back as JSON.
#include <nlohmann/json.hpp>

#include "arbiter/arbvp/exec_io.h"
#include "arbiter/runtime/worker.h"

namespace arbiter::runtime {

WorkerStatus RunArbInWorker(const ExecOptions& options, const WorkerLimits& limits,
                            const ArbPrograms& programs, const arbvp::ExecInputs& inputs,
                            std::vector<arbvp::VectorResult>* results, std::string* error) {
  auto job = [&](std::string* payload, std::string* job_error) {
    std::unique_ptr<ArbExecutor> executor = CreateArbExecutor(options, job_error);
    if (!executor) return false;
    std::vector<arbvp::VectorResult> out;
    if (!executor->Run(programs, inputs, &out, job_error)) return false;
    *payload = arbvp::ResultsToJson(out, /*with_bindings=*/true).dump();
    return true;
  };
  std::string payload;
  WorkerStatus status = RunInWorker(limits, job, &payload, error);
  if (status != WorkerStatus::Ok) return status;
  nlohmann::json json = nlohmann::json::parse(payload, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded() || !arbvp::ResultsFromJson(json, results, error)) {
    if (json.is_discarded()) *error = "the worker's answer is not JSON";
    return WorkerStatus::Crashed;
  }
  return WorkerStatus::Ok;
}

}  // namespace arbiter::runtime
