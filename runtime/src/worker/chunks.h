// Running a batch in worker processes by chunks (verify's programs, run's tests): each
// worker pays one process and GL context start-up per chunk, so chunks should be large; the
// last worker to finish sets the wall time, so they should be many enough to balance the
// workers.
#pragma once

#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "arbiter/runtime/worker.h"

namespace arbiter::runtime {

// A batch of items run in worker processes, -j at a time, in chunks: each chunk's job
// answers with a JSON array of one entry per item of the chunk.
struct ChunkedBatch {
  size_t items = 0;
  size_t workers = 1;     // processes at a time
  size_t per_worker = 1;  // chunks per worker (PlanChunks)
  size_t largest = 1;     // items per chunk at most
  WorkerLimits limits;    // per item: a worker's time limit covers its chunk
  // The job of items [first, first + count).
  std::function<WorkerJob(size_t first, size_t count)> make_job;
  // Reads item `index`'s entry; false when it is not what the job writes.
  std::function<bool(size_t index, const nlohmann::json& entry)> read;
  // Item `index` got no answer: its job failed before running it (`environment`: no GL
  // context), or its worker died (crashed, hung, out of memory) even when it ran alone.
  std::function<void(size_t index, const std::string& error, bool environment)> failed;
};

// Runs the batch. A chunk of several items whose worker gives no readable answer is run
// again one item per worker, so that only the guilty item gets the error; a chunk of one item
// is not run again.
void RunChunked(const ChunkedBatch& batch);

}  // namespace arbiter::runtime
