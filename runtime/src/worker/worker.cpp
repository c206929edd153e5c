// RunInWorker: fork, run the job in the child under RLIMIT_AS, read its answer through a
// pipe with a deadline, and turn every way the child can die into a WorkerStatus.
#include "arbiter/runtime/worker.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <new>
#include <thread>

#if defined(__SANITIZE_ADDRESS__)
#define ARBITER_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ARBITER_SANITIZED 1
#endif
#endif

namespace arbiter::runtime {
namespace {

using Clock = std::chrono::steady_clock;

// The first byte the child writes: how the job ended.
constexpr char kOk = 'O';
constexpr char kFailed = 'F';
constexpr char kOutOfMemory = 'M';

void WriteAll(int fd, const char* data, size_t size) {
  while (size > 0) {
    ssize_t n = write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent is gone: nobody to tell
    data += n;
    size -= static_cast<size_t>(n);
  }
}

[[noreturn]] void RunChild(int fd, const WorkerLimits& limits, const WorkerJob& job) {
  // Die with the parent rather than run on as an orphan.
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  // Drop the descriptors inherited from the parent (other threads' worker pipes among them:
  // a copy of another worker's write end would hold back that worker's end of answer).
  if (fd > 3) close_range(3, static_cast<unsigned>(fd) - 1, 0);
  close_range(static_cast<unsigned>(fd) + 1, ~0U, 0);
#ifndef ARBITER_SANITIZED
  rlimit limit{limits.memory_bytes, limits.memory_bytes};
  setrlimit(RLIMIT_AS, &limit);
#else
  (void)limits;
#endif
  std::string payload;
  std::string error;
  char status = kFailed;
  try {
    status = job(&payload, &error) ? kOk : kFailed;
  } catch (const std::bad_alloc&) {
    status = kOutOfMemory;
  } catch (const std::exception& e) {
    error = fmt::format("internal error in the worker: {}", e.what());
  }
  std::string answer(1, status);
  answer += status == kOk ? payload : error;
  WriteAll(fd, answer.data(), answer.size());
  close(fd);
  // No exit handlers or destructors: they belong to the parent's copy of the process.
  _exit(0);
}

std::string Describe(int wait_status) {
  if (WIFSIGNALED(wait_status)) {
    int sig = WTERMSIG(wait_status);
    return fmt::format("the worker was killed by signal {} ({})", sig, strsignal(sig));
  }
  return fmt::format("the worker exited with code {} without an answer", WEXITSTATUS(wait_status));
}

// Waits for the child until `deadline`; false if it is still running then.
bool Reap(pid_t pid, Clock::time_point deadline, int* wait_status) {
  while (true) {
    pid_t r = waitpid(pid, wait_status, WNOHANG);
    if (r == pid) return true;
    if (r < 0 && errno != EINTR) {
      *wait_status = 0;
      return true;
    }
    if (Clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

}  // namespace

WorkerStatus RunInWorker(const WorkerLimits& limits, const WorkerJob& job, std::string* payload,
                         std::string* error) {
  payload->clear();
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    *error = fmt::format("cannot create a pipe for the worker: {}", strerror(errno));
    return WorkerStatus::SpawnFailed;
  }
  pid_t pid = fork();
  if (pid < 0) {
    *error = fmt::format("cannot start a worker process: {}", strerror(errno));
    close(fds[0]);
    close(fds[1]);
    return WorkerStatus::SpawnFailed;
  }
  if (pid == 0) {
    close(fds[0]);
    RunChild(fds[1], limits, job);
  }
  close(fds[1]);

  const auto deadline = Clock::now() + std::chrono::milliseconds(limits.timeout_ms);
  std::string answer;
  bool timed_out = false;
  char buffer[65536];
  while (true) {
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    int ready = poll(&p, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) {
      timed_out = ready == 0;
      break;
    }
    ssize_t n = read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of the answer: the child closed its end
    answer.append(buffer, static_cast<size_t>(n));
  }
  close(fds[0]);

  int wait_status = 0;
  if (timed_out || !Reap(pid, deadline + std::chrono::seconds(5), &wait_status)) {
    kill(pid, SIGKILL);
    waitpid(pid, &wait_status, 0);
    *error = fmt::format("the worker ran past its time limit of {} ms and was stopped",
                         limits.timeout_ms);
    return WorkerStatus::TimedOut;
  }
  if (answer.empty() || !WIFEXITED(wait_status) || WEXITSTATUS(wait_status) != 0) {
    *error = Describe(wait_status);
    return WorkerStatus::Crashed;
  }
  switch (answer[0]) {
    case kOk:
      *payload = answer.substr(1);
      return WorkerStatus::Ok;
    case kOutOfMemory:
      *error =
          fmt::format("the worker ran out of memory (limit {} MiB)", limits.memory_bytes >> 20);
      return WorkerStatus::OutOfMemory;
    default:
      *error = answer.substr(1);
      return WorkerStatus::JobFailed;
  }
}

}  // namespace arbiter::runtime
