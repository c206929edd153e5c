// Command-line inputs: directory expansion, reading files and stdin, shared options.
#include <fmt/format.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <thread>

#include "cli.h"

namespace arbiter::cli {
namespace {

// A thread costs its start and a malloc arena of its own, and small inputs contend for the
// file system more than they compute: the 563 ARB programs of the corpus check in 14 ms on
// one thread and 17 on two (docs/performance.md). So a batch runs on the calling thread
// until it has lasted this long, and only then on -j threads.
constexpr auto kAlone = std::chrono::milliseconds(20);

// Reading failures are diagnostics without a file position.
const compiler::DiagnosticInfo kIoRead{"io-read", compiler::Severity::Error,
                                       "an input could not be read", ""};

// Program files found in directories: ARB .vp .fp .arbvp .arbfp, .txt files that start with an
// ARB header (formats.md), and GLSL .vert .vs .frag .fs.
bool IsProgramFile(const std::filesystem::path& path) {
  // The name as a view: a directory walk meets thousands of them (no path or string copies).
  const std::string_view name = path.native();
  const size_t dot = name.rfind('.');
  // No extension: no dot in the file name, or only a leading one (".vp" is a hidden file).
  if (dot == std::string_view::npos || dot == 0 || name[dot - 1] == '/' ||
      name.find('/', dot) != std::string_view::npos) {
    return false;
  }
  const std::string_view ext = name.substr(dot);
  if (ext == ".vp" || ext == ".fp" || ext == ".arbvp" || ext == ".arbfp") return true;
  if (ext == ".vert" || ext == ".vs" || ext == ".frag" || ext == ".fs") return true;
  if (ext != ".txt") return false;
  char head[5] = {};
  std::ifstream in(path, std::ios::binary);
  in.read(head, sizeof head);
  return in.gcount() == 5 && std::string_view(head, 5) == "!!ARB";
}

}  // namespace

Exit Worse(Exit a, Exit b) {
  auto rank = [](Exit e) {
    switch (e) {
      case Exit::Ok:
        return 0;
      case Exit::Rejected:
        return 1;
      case Exit::Usage:
        return 2;
      case Exit::Environment:
        return 3;
    }
    return 3;
  };
  return rank(a) >= rank(b) ? a : b;
}

std::vector<Input> ExpandInputs(const std::vector<std::string>& args) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Input> inputs;
  for (const std::string& arg : args) {
    if (arg == "-") {
      inputs.push_back({arg, "<stdin>", {}, false, {}});
      continue;
    }
    // A short batch runs on this thread (ParallelFor): one open tells a directory from a file
    // and reads the file, where a stat and a later open took five system calls. Past kAlone
    // a stat tells them apart and the workers read the files, in parallel.
    std::error_code ec;
    if (std::chrono::steady_clock::now() - start < kAlone) {
      Input input{arg, arg, {}, false, {}};
      std::string bytes;
      switch (compiler::ReadFileOrDirectory(arg, &bytes, &input.error)) {
        case compiler::ReadOutcome::Read:
          input.bytes = std::move(bytes);
          inputs.push_back(std::move(input));
          continue;
        case compiler::ReadOutcome::Failed:
          inputs.push_back(std::move(input));
          continue;
        case compiler::ReadOutcome::Directory:
          break;
      }
    } else if (!std::filesystem::is_directory(arg, ec)) {
      inputs.push_back({arg, arg, {}, false, {}});
      continue;
    }
    std::vector<std::string> found;
    auto options = std::filesystem::directory_options::skip_permission_denied;
    for (auto it = std::filesystem::recursive_directory_iterator(arg, options, ec);
         !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
      if (it->is_regular_file(ec) && IsProgramFile(it->path())) {
        found.push_back(it->path().generic_string());
      }
    }
    std::sort(found.begin(), found.end());
    if (found.empty()) {
      inputs.push_back({arg,
                        arg,
                        "no program files (.vp .fp .arbvp .arbfp, .txt with an ARB header) under "
                        "this directory",
                        false,
                        {}});
    }
    for (std::string& path : found) inputs.push_back({path, path, {}, true, {}});
  }
  return inputs;
}

std::unique_ptr<compiler::SourceFile> ReadInput(const Input& input, compiler::FileReport* report) {
  std::string bytes;
  std::string error = input.error;
  if (input.bytes) {
    bytes = std::move(*input.bytes);
    input.bytes.reset();
  } else if (!error.empty() || !compiler::ReadFileBytes(input.path, &bytes, &error)) {
    compiler::Diagnostic d;
    d.info = &kIoRead;
    d.severity = compiler::Severity::Error;
    d.path = input.display_path;
    d.message = fmt::format("cannot read '{}': {}", input.display_path, error);
    report->diagnostics.push_back(std::move(d));
    return nullptr;
  }
  return std::make_unique<compiler::SourceFile>(input.display_path, std::move(bytes));
}

void AddCommonOptions(CLI::App* app, CommonOptions* options, bool diagnostics) {
  app->add_option("files", options->files, "program files or directories ('-' reads stdin)")
      ->required();
  // SARIF reports diagnostics: info has none to give.
  app->add_option("--format", options->format, "output format")
      ->check(diagnostics ? CLI::IsMember({"text", "json", "sarif"})
                          : CLI::IsMember({"text", "json"}));
  app->add_option("--color", options->color, "colour text output")
      ->check(CLI::IsMember({"auto", "always", "never"}));
  app->add_option("--limits", options->limits,
                  "limit profile: spec-min, mesa, or a JSON file (default: portability "
                  "warnings)");
  app->add_option("--stage", options->stage, "program kind instead of the header's")
      ->check(CLI::IsMember({"arbvp", "arbfp", "vert", "frag"}));
  if (diagnostics) {
    app->add_option("--error-limit", options->error_limit,
                    "stop reporting errors of a file after N (0: no limit)")
        ->check(CLI::NonNegativeNumber);
    app->add_flag("-W,--Werror", options->werror, "treat warnings as errors");
    app->add_option("-j,--jobs", options->jobs, "worker threads (default: one per core)")
        ->check(CLI::NonNegativeNumber);
  }
}

void KeepMallocMemory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's own upper bound for its dynamic threshold
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  mallopt(M_TOP_PAD, 16 << 20);  // address space only: pages are touched as used
#endif
}

size_t ResolveJobs(const CommonOptions& options) {
  if (options.jobs > 0) return static_cast<size_t>(options.jobs);
  return std::max(1u, std::thread::hardware_concurrency());
}

void ParallelFor(size_t count, size_t threads, const std::function<void(size_t)>& body) {
  // Threads take indices in turn, so a slow input does not hold up a fixed share.
  std::atomic<size_t> next{0};
  auto work = [&] {
    for (size_t i = next++; i < count; i = next++) body(i);
  };
  // The calling thread starts alone and calls the others once the batch has lasted kAlone.
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> pool;
  for (size_t i = next++; i < count; i = next++) {
    body(i);
    if (pool.empty() && threads > 1 && next < count &&
        std::chrono::steady_clock::now() - start > kAlone) {
      for (size_t t = 1; t < std::min(threads, count - next + 1); ++t) pool.emplace_back(work);
    }
  }
  for (std::thread& t : pool) t.join();
}

bool ResolveLimits(const CommonOptions& options, std::optional<compiler::LimitProfile>* out) {
  if (options.limits.empty()) return true;
  std::string error;
  *out = compiler::LoadLimitProfile(options.limits, &error);
  if (!*out) {
    fmt::print(stderr, "arbiter: error: --limits: {}\n", error);
    return false;
  }
  return true;
}

bool ResolveStage(const CommonOptions& options, std::optional<arbvp::ProgramKind>* out) {
  if (options.stage == "arbvp") *out = arbvp::ProgramKind::Vertex;
  if (options.stage == "arbfp") *out = arbvp::ProgramKind::Fragment;
  return true;
}

std::optional<glsl::Stage> GlslStage(const CommonOptions& options, const Input& input) {
  if (options.stage == "vert") return glsl::Stage::Vertex;
  if (options.stage == "frag") return glsl::Stage::Fragment;
  if (!options.stage.empty()) return std::nullopt;  // --stage arbvp/arbfp
  return glsl::StageFromPath(input.path);
}

}  // namespace arbiter::cli
