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

// A thread costs its start (0.2 to 0.3 ms of a 3 ms check of ten ARB programs), so a batch
// runs on the calling thread until it has lasted this long, and then on -j threads: from
// there a second thread pays (the 563 ARB programs of the corpus check 1.13x faster than
// with a 20 ms window; docs/performance.md).
constexpr auto kAlone = std::chrono::milliseconds(2);

// Named files are read while the arguments are classified, for this long: one open tells a
// directory from a file and reads it (four system calls, where a stat and a later open took
// five). Past it a stat tells them apart and the workers read the files, so that a long
// batch does not hold every file in memory at once.
constexpr auto kReadAhead = std::chrono::milliseconds(20);

// When the batch began: the first call, which ExpandInputs makes before anything else.
std::chrono::steady_clock::time_point BatchStart() {
  static const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  return start;
}

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

constexpr auto kSkipDenied = std::filesystem::directory_options::skip_permission_denied;

// Adds the program files directly in `dir` to `found` and its subdirectories (not links to
// them, which are not followed) to `subdirectories`.
void ListDirectory(const std::filesystem::path& dir, std::vector<std::string>* found,
                   std::vector<std::filesystem::path>* subdirectories) {
  std::error_code ec;
  for (auto it = std::filesystem::directory_iterator(dir, kSkipDenied, ec);
       !ec && it != std::filesystem::directory_iterator(); it.increment(ec)) {
    if (it->is_directory(ec) && !it->is_symlink(ec)) {
      subdirectories->push_back(it->path());
    } else if (it->is_regular_file(ec) && IsProgramFile(it->path())) {
      found->push_back(it->path().generic_string());
    }
  }
}

// Adds the program files anywhere under `dir` to `found`.
void WalkDirectory(const std::filesystem::path& dir, std::vector<std::string>* found) {
  std::error_code ec;
  for (auto it = std::filesystem::recursive_directory_iterator(dir, kSkipDenied, ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
    if (it->is_regular_file(ec) && IsProgramFile(it->path())) {
      found->push_back(it->path().generic_string());
    }
  }
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

std::vector<Input> ExpandInputs(const std::vector<std::string>& args, size_t threads) {
  BatchStart();
  // Each argument is classified first, on the -j threads: for a long list of names that is
  // a system call or more per name, on one thread the largest serial part of a big batch.
  std::vector<Input> named(args.size());
  std::vector<char> directory(args.size(), 0);
  std::vector<std::vector<std::string>> found(args.size());
  std::vector<std::vector<std::filesystem::path>> subdirectories(args.size());
  ParallelFor(args.size(), threads, [&](size_t i) {
    const std::string& arg = args[i];
    Input& input = named[i];
    input = {arg, arg == "-" ? "<stdin>" : arg, {}, false, {}};
    if (arg == "-") return;
    if (std::chrono::steady_clock::now() - BatchStart() < kReadAhead) {
      std::string bytes;
      switch (compiler::ReadFileOrDirectory(arg, &bytes, &input.error)) {
        case compiler::ReadOutcome::Read:
          input.bytes = std::move(bytes);
          return;
        case compiler::ReadOutcome::Failed:
          return;
        case compiler::ReadOutcome::Directory:
          break;
      }
    } else if (std::error_code ec; !std::filesystem::is_directory(arg, ec)) {
      return;
    }
    directory[i] = 1;
    ListDirectory(arg, &found[i], &subdirectories[i]);
  });
  // The subdirectories of the directories named are walked in parallel too.
  std::vector<std::pair<size_t, const std::filesystem::path*>> walks;
  for (size_t i = 0; i < args.size(); ++i) {
    for (const std::filesystem::path& sub : subdirectories[i]) walks.emplace_back(i, &sub);
  }
  std::vector<std::vector<std::string>> walked(walks.size());
  ParallelFor(walks.size(), threads,
              [&](size_t w) { WalkDirectory(*walks[w].second, &walked[w]); });
  for (size_t w = 0; w < walks.size(); ++w) {
    std::vector<std::string>& into = found[walks[w].first];
    into.insert(into.end(), std::make_move_iterator(walked[w].begin()),
                std::make_move_iterator(walked[w].end()));
  }

  std::vector<Input> inputs;
  inputs.reserve(args.size());
  for (size_t i = 0; i < args.size(); ++i) {
    if (!directory[i]) {
      inputs.push_back(std::move(named[i]));
      continue;
    }
    std::sort(found[i].begin(), found[i].end());
    if (found[i].empty()) {
      inputs.push_back({args[i],
                        args[i],
                        "no program files (.vp .fp .arbvp .arbfp, .txt with an ARB header) under "
                        "this directory",
                        false,
                        {}});
    }
    for (std::string& path : found[i]) inputs.push_back({path, path, {}, true, {}});
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
  // The calling thread starts alone and calls the others once the batch has lasted kAlone,
  // its argument expansion included.
  std::vector<std::thread> pool;
  for (size_t i = next++; i < count; i = next++) {
    body(i);
    if (pool.empty() && threads > 1 && next < count &&
        std::chrono::steady_clock::now() - BatchStart() > kAlone) {
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
