// RunChunked (verify's and run's batches): a chunk whose worker gives no readable answer is
// run again one item per worker, so that only the guilty item gets the error; a job that
// fails (no GL context) fails its whole chunk as an environment error.
#include "worker/chunks.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace arbiter::runtime {
namespace {

// Items 0..9 in four chunks ([0,3) [3,6) [6,9) [9,10)) on two workers. Each job answers one
// entry per item, the item's index, unless `behave` says otherwise for its chunk.
struct Recorder {
  std::vector<int> read = std::vector<int>(10, -1);
  struct Failure {
    std::string error;
    bool environment = false;
  };
  std::map<size_t, Failure> failed;
};

ChunkedBatch MakeBatch(Recorder* r,
                       std::function<bool(size_t, size_t, std::string*, std::string*)> behave) {
  ChunkedBatch batch;
  batch.items = 10;
  batch.workers = 2;
  batch.per_worker = 2;
  batch.largest = 256;
  batch.make_job = [behave](size_t first, size_t count) -> WorkerJob {
    return [=](std::string* payload, std::string* error) {
      return behave(first, count, payload, error);
    };
  };
  batch.read = [r](size_t i, const nlohmann::json& entry) {
    if (!entry.is_number_integer()) return false;
    r->read[i] = entry.get<int>();
    return true;
  };
  batch.failed = [r](size_t i, const std::string& error, bool environment) {
    r->failed[i] = {error, environment};
  };
  return batch;
}

std::string Indices(size_t first, size_t count) {
  nlohmann::json answer = nlohmann::json::array();
  for (size_t i = first; i < first + count; ++i) answer.push_back(i);
  return answer.dump();
}

TEST(RunChunked, AnswersEveryItemOfHealthyChunks) {
  Recorder r;
  RunChunked(MakeBatch(&r, [](size_t first, size_t count, std::string* payload, std::string*) {
    *payload = Indices(first, count);
    return true;
  }));
  for (int i = 0; i < 10; ++i) EXPECT_EQ(r.read[i], i);
  EXPECT_TRUE(r.failed.empty());
}

TEST(RunChunked, BlamesOnlyTheItemWhoseWorkerDies) {
  Recorder r;
  RunChunked(MakeBatch(&r, [](size_t first, size_t count, std::string* payload, std::string*) {
    if (first <= 4 && 4 < first + count) std::_Exit(3);  // item 4 kills its worker
    *payload = Indices(first, count);
    return true;
  }));
  // Items 3 and 5 shared item 4's chunk: run again alone, they answer.
  for (int i = 0; i < 10; ++i) EXPECT_EQ(r.read[i], i == 4 ? -1 : i) << "item " << i;
  ASSERT_EQ(r.failed.size(), 1u);
  ASSERT_EQ(r.failed.count(4), 1u);
  EXPECT_FALSE(r.failed[4].environment);
  EXPECT_NE(r.failed[4].error.find("without an answer"), std::string::npos) << r.failed[4].error;
}

// Item 9 is a chunk of its own: when its worker dies it is not run again (a hanging test
// would cost twice its time limit). Jobs run in child processes: they count their runs in a
// file.
TEST(RunChunked, DoesNotRerunAChunkOfOneItem) {
  Recorder r;
  const std::string log = ::testing::TempDir() + "chunks_test_runs_of_item_9";
  std::remove(log.c_str());
  RunChunked(MakeBatch(&r, [log](size_t first, size_t count, std::string* payload, std::string*) {
    if (first == 9) {
      if (FILE* f = std::fopen(log.c_str(), "a")) {
        std::fputs("run\n", f);
        std::fclose(f);
      }
      std::_Exit(3);
    }
    *payload = Indices(first, count);
    return true;
  }));
  EXPECT_EQ(r.failed.count(9), 1u);
  EXPECT_EQ(r.failed.size(), 1u);
  std::string runs;
  if (FILE* f = std::fopen(log.c_str(), "r")) {
    char buffer[64];
    while (std::fgets(buffer, sizeof buffer, f) != nullptr) runs += buffer;
    std::fclose(f);
  }
  EXPECT_EQ(runs, "run\n");
  std::remove(log.c_str());
}

TEST(RunChunked, RerunsAChunkWhoseAnswerHasTheWrongShape) {
  Recorder r;
  RunChunked(MakeBatch(&r, [](size_t first, size_t count, std::string* payload, std::string*) {
    // A chunk of several items answers one entry short; single items answer right.
    *payload = Indices(first, count > 1 && first == 6 ? count - 1 : count);
    return true;
  }));
  for (int i = 0; i < 10; ++i) EXPECT_EQ(r.read[i], i) << "item " << i;
  EXPECT_TRUE(r.failed.empty());
}

TEST(RunChunked, FailsAWholeChunkWhenItsJobFails) {
  Recorder r;
  RunChunked(MakeBatch(&r, [](size_t first, size_t count, std::string* payload, std::string* e) {
    if (first == 3) {
      *e = "no GL context";
      return false;
    }
    *payload = Indices(first, count);
    return true;
  }));
  for (int i = 0; i < 10; ++i) {
    const bool in_chunk = i >= 3 && i < 6;
    EXPECT_EQ(r.read[i], in_chunk ? -1 : i) << "item " << i;
    EXPECT_EQ(r.failed.count(i), in_chunk ? 1u : 0u) << "item " << i;
    if (in_chunk) {
      EXPECT_EQ(r.failed[i].error, "no GL context");
      EXPECT_TRUE(r.failed[i].environment);
    }
  }
}

}  // namespace
}  // namespace arbiter::runtime
