// The worker process that isolates the GL driver: a job runs in a forked child with a time
// limit and a memory limit, so a crash, hang or runaway allocation inside Mesa becomes a
// clean error for the caller (docs/design/architecture.md, Execution design).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "arbiter/arbvp/exec.h"
#include "arbiter/runtime/exec.h"

namespace arbiter::runtime {

struct WorkerLimits {
  int timeout_ms = 60000;
  // RLIMIT_AS of the child. Not applied in sanitizer builds (their shadow memory needs
  // terabytes of address space).
  uint64_t memory_bytes = uint64_t{8} << 30;
};

enum class WorkerStatus : uint8_t {
  Ok,           // the job succeeded and returned its payload
  JobFailed,    // the job reported an error (in `error`)
  Crashed,      // the child died from a signal or exited without an answer
  TimedOut,     // killed at the time limit
  OutOfMemory,  // an allocation failed under the memory limit
  SpawnFailed,  // no child could be started
};

// A job: fills `payload` and returns true, or sets `error` and returns false. Runs in the
// child, which has a copy of the caller's memory (fork): the caller must not hold GL state
// or threads the job relies on.
using WorkerJob = std::function<bool(std::string* payload, std::string* error)>;

// Runs `job` in a child process and waits at most limits.timeout_ms for it. On anything but
// Ok, `error` says what happened in lower case ("the worker was killed by signal 11
// (segmentation fault)", "the worker ran past its time limit of 5000 ms").
WorkerStatus RunInWorker(const WorkerLimits& limits, const WorkerJob& job, std::string* payload,
                         std::string* error);

struct WorkerResult {
  WorkerStatus status = WorkerStatus::SpawnFailed;
  std::string payload;  // when Ok
  std::string error;    // otherwise
};

// Runs `count` jobs (make_job(i) gives job i), each in its own child process, at most
// `parallel` at a time, each with `limits`. Every child is forked from the calling thread
// (forking while other threads allocate can deadlock the child under a sanitizer's
// allocator), so callers get parallel workers without threads. Results in job order.
void RunInWorkers(const WorkerLimits& limits, size_t count, size_t parallel,
                  const std::function<WorkerJob(size_t)>& make_job,
                  std::vector<WorkerResult>* results);

// ArbExecutor::Run in a worker process: creates the executor there, runs, and carries the
// results back. Returns Ok and fills `results`, or another status with `error` set.
WorkerStatus RunArbInWorker(const ExecOptions& options, const WorkerLimits& limits,
                            const ArbPrograms& programs, const arbvp::ExecInputs& inputs,
                            std::vector<arbvp::VectorResult>* results, std::string* error);

}  // namespace arbiter::runtime
