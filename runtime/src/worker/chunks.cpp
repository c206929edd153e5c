// RunChunked: see chunks.h.
#include "worker/chunks.h"

#include <algorithm>
#include <cstdint>

namespace arbiter::runtime {
namespace {

// Items [first, first + count) of a batch.
struct Chunk {
  size_t first = 0;
  size_t count = 0;
};

// About `per_worker` chunks per worker, of at most `largest` items each.
std::vector<Chunk> PlanChunks(const ChunkedBatch& batch) {
  const size_t share = std::max<size_t>(batch.workers, 1) * std::max<size_t>(batch.per_worker, 1);
  const size_t size = std::clamp<size_t>((batch.items + share - 1) / share, 1, batch.largest);
  std::vector<Chunk> chunks;
  for (size_t first = 0; first < batch.items; first += size) {
    chunks.push_back({first, std::min(size, batch.items - first)});
  }
  return chunks;
}

// Runs `chunks`; returns those whose worker gave no readable answer, with the reason in
// `errors`.
std::vector<Chunk> RunChunks(const ChunkedBatch& batch, const std::vector<Chunk>& chunks,
                             std::vector<std::string>* errors) {
  size_t largest = 1;
  for (const Chunk& c : chunks) largest = std::max(largest, c.count);
  WorkerLimits limits = batch.limits;
  limits.timeout_ms = static_cast<int>(std::min<int64_t>(
      static_cast<int64_t>(limits.timeout_ms) * static_cast<int64_t>(largest), 24 * 3600 * 1000));
  std::vector<WorkerResult> outcomes;
  RunInWorkers(
      limits, chunks.size(), batch.workers,
      [&](size_t c) { return batch.make_job(chunks[c].first, chunks[c].count); }, &outcomes);
  std::vector<Chunk> failed;
  errors->clear();
  for (size_t c = 0; c < chunks.size(); ++c) {
    const Chunk& chunk = chunks[c];
    const WorkerResult& outcome = outcomes[c];
    if (outcome.status == WorkerStatus::JobFailed) {
      for (size_t i = chunk.first; i < chunk.first + chunk.count; ++i) {
        batch.failed(i, outcome.error, /*environment=*/true);
      }
      continue;
    }
    nlohmann::json json;
    if (outcome.status == WorkerStatus::Ok) {
      json = nlohmann::json::parse(outcome.payload, nullptr, /*allow_exceptions=*/false);
    }
    bool read = json.is_array() && json.size() == chunk.count;
    for (size_t i = 0; read && i < chunk.count; ++i) read = batch.read(chunk.first + i, json[i]);
    if (!read) {
      failed.push_back(chunk);
      errors->push_back(outcome.status == WorkerStatus::Ok
                            ? "the worker's answer is not the expected JSON"
                            : outcome.error);
    }
  }
  return failed;
}

}  // namespace

void RunChunked(const ChunkedBatch& batch) {
  std::vector<std::string> errors;
  const std::vector<Chunk> failed = RunChunks(batch, PlanChunks(batch), &errors);
  // A chunk of one item already ran alone: its failure is final (running it again would
  // make a hanging test cost twice its time limit). The others run again item by item.
  std::vector<Chunk> singles;
  for (size_t f = 0; f < failed.size(); ++f) {
    const Chunk& c = failed[f];
    if (c.count == 1) {
      batch.failed(c.first, errors[f], /*environment=*/false);
      continue;
    }
    for (size_t i = c.first; i < c.first + c.count; ++i) singles.push_back({i, 1});
  }
  if (singles.empty()) return;
  const std::vector<Chunk> guilty = RunChunks(batch, singles, &errors);
  for (size_t g = 0; g < guilty.size(); ++g)
    batch.failed(guilty[g].first, errors[g], /*environment=*/false);
}

}  // namespace arbiter::runtime
