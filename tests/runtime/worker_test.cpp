// The worker process: every way a job can end becomes a status, never a crash or a hang of
// the caller.
#include "arbiter/runtime/worker.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <new>
#include <thread>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)
#define ARBITER_TEST_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ARBITER_TEST_SANITIZED 1
#endif
#endif

namespace arbiter::runtime {
namespace {

TEST(Worker, ReturnsThePayloadOfASuccessfulJob) {
  std::string payload, error;
  WorkerLimits limits;
  WorkerStatus status = RunInWorker(
      limits,
      [](std::string* out, std::string*) {
        *out = std::string(200000, 'x') + "end";  // larger than a pipe buffer
        return true;
      },
      &payload, &error);
  ASSERT_EQ(status, WorkerStatus::Ok) << error;
  EXPECT_EQ(payload.size(), 200003u);
  EXPECT_EQ(payload.substr(200000), "end");
}

TEST(Worker, CarriesTheErrorOfAFailedJob) {
  std::string payload, error;
  WorkerStatus status = RunInWorker(
      WorkerLimits{},
      [](std::string*, std::string* e) {
        *e = "mesa rejected the program";
        return false;
      },
      &payload, &error);
  EXPECT_EQ(status, WorkerStatus::JobFailed);
  EXPECT_EQ(error, "mesa rejected the program");
}

TEST(Worker, ReportsACrashWithItsSignal) {
  std::string payload, error;
  WorkerStatus status = RunInWorker(
      WorkerLimits{},
      [](std::string*, std::string*) {
        raise(SIGSEGV);
        return true;
      },
      &payload, &error);
  EXPECT_EQ(status, WorkerStatus::Crashed);
#ifndef ARBITER_TEST_SANITIZED
  EXPECT_NE(error.find("signal 11"), std::string::npos) << error;
#else
  // AddressSanitizer catches the signal itself and exits with code 1.
  EXPECT_NE(error.find("without an answer"), std::string::npos) << error;
#endif
}

TEST(Worker, ReportsAnExitWithoutAnswerAsACrash) {
  std::string payload, error;
  WorkerStatus status = RunInWorker(
      WorkerLimits{}, [](std::string*, std::string*) -> bool { _exit(7); }, &payload, &error);
  EXPECT_EQ(status, WorkerStatus::Crashed);
  EXPECT_NE(error.find("code 7"), std::string::npos) << error;
}

TEST(Worker, StopsAJobAtItsTimeLimit) {
  std::string payload, error;
  WorkerLimits limits;
  limits.timeout_ms = 300;
  auto start = std::chrono::steady_clock::now();
  WorkerStatus status = RunInWorker(
      limits,
      [](std::string*, std::string*) {
        while (true) std::this_thread::sleep_for(std::chrono::seconds(1));
        return true;
      },
      &payload, &error);
  EXPECT_EQ(status, WorkerStatus::TimedOut);
  EXPECT_NE(error.find("300 ms"), std::string::npos) << error;
  // The caller is not held beyond the limit (a generous bound: this asserts no hang, not speed).
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
}

TEST(Worker, ReportsAnAllocationFailure) {
  std::string payload, error;
  WorkerStatus status = RunInWorker(
      WorkerLimits{}, [](std::string*, std::string*) -> bool { throw std::bad_alloc(); }, &payload,
      &error);
  EXPECT_EQ(status, WorkerStatus::OutOfMemory);
  EXPECT_NE(error.find("out of memory"), std::string::npos) << error;
}

#ifndef ARBITER_TEST_SANITIZED
// The memory limit is real: a job allocating past it fails in the child only. (Sanitizer
// builds do not apply RLIMIT_AS: their shadow memory needs the address space.)
TEST(Worker, EnforcesTheMemoryLimit) {
  std::string payload, error;
  WorkerLimits limits;
  limits.memory_bytes = uint64_t{512} << 20;
  WorkerStatus status = RunInWorker(
      limits,
      [](std::string* out, std::string*) {
        std::vector<char> big(size_t{2} << 30, 1);
        *out = std::to_string(big.size());
        return true;
      },
      &payload, &error);
  EXPECT_EQ(status, WorkerStatus::OutOfMemory) << error;
}
#endif

TEST(Worker, RunsManyJobsInParallelEachToItsOwnEnd) {
  // Job i answers its index; job 1 crashes, job 3 hangs past the limit. Two at a time.
  WorkerLimits limits;
  limits.timeout_ms = 1000;
  std::vector<WorkerResult> results;
  const auto start = std::chrono::steady_clock::now();
  RunInWorkers(
      limits, 6, 2,
      [](size_t i) -> WorkerJob {
        return [i](std::string* out, std::string*) {
          if (i == 1) raise(SIGSEGV);
          if (i == 3) std::this_thread::sleep_for(std::chrono::seconds(30));
          *out = std::to_string(i) + std::string(100000, '.');  // larger than a pipe buffer
          return true;
        };
      },
      &results);
  ASSERT_EQ(results.size(), 6u);
  for (size_t i : {0u, 2u, 4u, 5u}) {
    ASSERT_EQ(results[i].status, WorkerStatus::Ok) << i << ": " << results[i].error;
    EXPECT_EQ(results[i].payload.substr(0, 1), std::to_string(i));
    EXPECT_EQ(results[i].payload.size(), 100001u);
  }
  EXPECT_EQ(results[1].status, WorkerStatus::Crashed);
  EXPECT_EQ(results[3].status, WorkerStatus::TimedOut);
  // The hang cost one time limit, not one per job behind it.
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
}

}  // namespace
}  // namespace arbiter::runtime
