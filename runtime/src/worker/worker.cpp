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

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <new>
#include <thread>
#include <utility>
#include <vector>

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

std::string Describe(int wait_status, const WorkerLimits& limits) {
  if (WIFSIGNALED(wait_status)) {
    int sig = WTERMSIG(wait_status);
#ifndef ARBITER_SANITIZED
    // Drivers do not check every allocation: at the memory limit they crash instead.
    if (sig == SIGSEGV || sig == SIGBUS || sig == SIGABRT) {
      return fmt::format("the worker was killed by signal {} ({}); its memory limit is {} MiB", sig,
                         strsignal(sig), limits.memory_bytes >> 20);
    }
#else
    (void)limits;
#endif
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

// One running child: its pid, the read end of its pipe, its deadline and what it said.
struct Child {
  pid_t pid = -1;
  int fd = -1;
  Clock::time_point deadline;
  std::string answer;
  bool timed_out = false;
};

// Forks a child running `job`; false (with `error`) when none could be started.
bool Spawn(const WorkerLimits& limits, const WorkerJob& job, Child* child, std::string* error) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    *error = fmt::format("cannot create a pipe for the worker: {}", strerror(errno));
    return false;
  }
  pid_t pid = fork();
  if (pid < 0) {
    *error = fmt::format("cannot start a worker process: {}", strerror(errno));
    close(fds[0]);
    close(fds[1]);
    return false;
  }
  if (pid == 0) {
    close(fds[0]);
    RunChild(fds[1], limits, job);
  }
  close(fds[1]);
  *child = Child{};
  child->pid = pid;
  child->fd = fds[0];
  child->deadline = Clock::now() + std::chrono::milliseconds(limits.timeout_ms);
  return true;
}

// Reads what the child has written; false once its answer is complete (end of file, an
// error, or the deadline passed).
bool Pump(Child* child) {
  char buffer[65536];
  while (true) {
    ssize_t n = read(child->fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return true;
    if (n <= 0) return false;  // end of the answer: the child closed its end
    child->answer.append(buffer, static_cast<size_t>(n));
    if (static_cast<size_t>(n) < sizeof buffer) return true;
  }
}

// Closes the pipe, reaps the child and turns its end into a status.
WorkerStatus Finish(const WorkerLimits& limits, Child* child, std::string* payload,
                    std::string* error) {
  close(child->fd);
  int wait_status = 0;
  if (child->timed_out ||
      !Reap(child->pid, child->deadline + std::chrono::seconds(5), &wait_status)) {
    kill(child->pid, SIGKILL);
    waitpid(child->pid, &wait_status, 0);
    *error = fmt::format("the worker ran past its time limit of {} ms and was stopped",
                         limits.timeout_ms);
    return WorkerStatus::TimedOut;
  }
  const std::string& answer = child->answer;
  if (answer.empty() || !WIFEXITED(wait_status) || WEXITSTATUS(wait_status) != 0) {
    *error = Describe(wait_status, limits);
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

}  // namespace

WorkerStatus RunInWorker(const WorkerLimits& limits, const WorkerJob& job, std::string* payload,
                         std::string* error) {
  std::vector<WorkerResult> results;
  RunInWorkers(
      limits, 1, 1, [&](size_t) { return job; }, &results);
  *payload = std::move(results[0].payload);
  *error = std::move(results[0].error);
  return results[0].status;
}

void RunInWorkers(const WorkerLimits& limits, size_t count, size_t parallel,
                  const std::function<WorkerJob(size_t)>& make_job,
                  std::vector<WorkerResult>* results) {
  results->assign(count, WorkerResult{});
  parallel = std::max<size_t>(parallel, 1);
  std::vector<std::pair<size_t, Child>> running;
  size_t next = 0;
  while (next < count || !running.empty()) {
    while (next < count && running.size() < parallel) {
      Child child;
      WorkerResult& r = (*results)[next];
      if (Spawn(limits, make_job(next), &child, &r.error)) {
        fcntl(child.fd, F_SETFL, O_NONBLOCK);
        running.emplace_back(next, std::move(child));
      } else {
        r.status = WorkerStatus::SpawnFailed;
      }
      ++next;
    }
    if (running.empty()) continue;
    // Wait for an answer or the nearest deadline.
    std::vector<pollfd> fds;
    Clock::time_point nearest = running[0].second.deadline;
    for (const auto& [index, child] : running) {
      fds.push_back(pollfd{child.fd, POLLIN, 0});
      nearest = std::min(nearest, child.deadline);
    }
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(nearest - Clock::now());
    int ready = poll(fds.data(), fds.size(), static_cast<int>(std::max<int64_t>(left.count(), 0)));
    if (ready < 0 && errno != EINTR) ready = 0;
    const Clock::time_point now = Clock::now();
    for (size_t i = running.size(); i-- > 0;) {
      Child& child = running[i].second;
      bool done = false;
      if (fds[i].revents != 0) done = !Pump(&child);
      if (!done && now >= child.deadline) {
        child.timed_out = true;
        done = true;
      }
      if (!done) continue;
      WorkerResult& r = (*results)[running[i].first];
      r.status = Finish(limits, &child, &r.payload, &r.error);
      running.erase(running.begin() + static_cast<std::ptrdiff_t>(i));
    }
  }
}

}  // namespace arbiter::runtime
