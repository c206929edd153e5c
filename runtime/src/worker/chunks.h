// Splitting a batch into chunks for worker processes: each worker pays one process and GL
// context start-up per chunk, so chunks should be large; the last worker to finish sets the
// wall time, so they should be many enough to balance the workers.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "arbiter/runtime/worker.h"

namespace arbiter::runtime {

// Items [first, first + count) of a batch.
struct Chunk {
  size_t first = 0;
  size_t count = 0;
};

// About `per_worker` chunks per worker, of at most `largest` items each.
inline std::vector<Chunk> PlanChunks(size_t items, size_t workers, size_t per_worker,
                                     size_t largest) {
  const size_t share = std::max<size_t>(workers, 1) * std::max<size_t>(per_worker, 1);
  const size_t size = std::clamp<size_t>((items + share - 1) / share, 1, largest);
  std::vector<Chunk> chunks;
  for (size_t first = 0; first < items; first += size) {
    chunks.push_back({first, std::min(size, items - first)});
  }
  return chunks;
}

// Each item of `chunks` as a chunk of its own (rerunning a chunk whose worker died).
inline std::vector<Chunk> Singles(const std::vector<Chunk>& chunks) {
  std::vector<Chunk> singles;
  for (const Chunk& c : chunks) {
    for (size_t i = c.first; i < c.first + c.count; ++i) singles.push_back({i, 1});
  }
  return singles;
}

// Runs make_job(chunk) for every chunk in worker processes, `parallel` at a time, each with
// `per_item` limits except that the time limit covers the largest chunk's items. Results in
// chunk order.
inline std::vector<WorkerResult> RunChunksInWorkers(
    const WorkerLimits& per_item, const std::vector<Chunk>& chunks, size_t parallel,
    const std::function<WorkerJob(const Chunk&)>& make_job) {
  size_t largest = 1;
  for (const Chunk& c : chunks) largest = std::max(largest, c.count);
  WorkerLimits limits = per_item;
  limits.timeout_ms = static_cast<int>(std::min<int64_t>(
      static_cast<int64_t>(limits.timeout_ms) * static_cast<int64_t>(largest), 24 * 3600 * 1000));
  std::vector<WorkerResult> outcomes;
  RunInWorkers(
      limits, chunks.size(), parallel, [&](size_t c) { return make_job(chunks[c]); }, &outcomes);
  return outcomes;
}

}  // namespace arbiter::runtime
