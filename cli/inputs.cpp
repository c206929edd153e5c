// Command-line inputs: directory expansion, reading files and stdin, shared options.
#include <dirent.h>
#include <fmt/format.h>
#include <sys/stat.h>
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
#include "options.h"

namespace arbiter::cli {
namespace {

// A thread costs its start (0.2 to 0.3 ms of a 3 ms check of ten ARB programs), so a batch
// runs on the calling thread until it has lasted this long, and then on -j threads: from
// there a second thread pays (the 563 ARB programs of the corpus check 1.11x faster than
// with a 20 ms window; docs/performance.md, ARB).
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
// ARB header (docs/design/formats.md), and GLSL files whose name gives the stage
// (glsl::StageFromPath).
bool IsProgramFile(const std::string& path) {
  const std::string_view name = path;
  const size_t dot = name.rfind('.');
  // No extension: no dot in the file name, or only a leading one (".vp" is a hidden file).
  if (dot == std::string_view::npos || dot == 0 || name[dot - 1] == '/' ||
      name.find('/', dot) != std::string_view::npos) {
    return false;
  }
  const std::string_view ext = name.substr(dot);
  if (ext == ".vp" || ext == ".fp" || ext == ".arbvp" || ext == ".arbfp") return true;
  // A bare .glsl in a directory is an include file or a library as often as a shader: only
  // names that say the stage are picked up (a .glsl named on the command line is checked, and
  // told to give its stage).
  if (glsl::StageFromPath(name)) return true;
  if (ext != ".txt") return false;
  char head[5] = {};
  std::ifstream in(path, std::ios::binary);
  in.read(head, sizeof head);
  return in.gcount() == 5 && std::string_view(head, 5) == "!!ARB";
}

// What a directory entry is, links followed except to directories (a walk does not follow
// those, as `find` does not): most file systems say it in the entry, others need an lstat.
enum class EntryKind { Directory, File, Other };
EntryKind KindOf(const dirent& entry, const std::string& path) {
  unsigned char type = entry.d_type;
  struct stat st;
  if (type == DT_UNKNOWN) {
    if (lstat(path.c_str(), &st) != 0) return EntryKind::Other;
    if (S_ISDIR(st.st_mode)) return EntryKind::Directory;
    if (S_ISREG(st.st_mode)) return EntryKind::File;
    type = S_ISLNK(st.st_mode) ? DT_LNK : DT_UNKNOWN;
  }
  if (type == DT_DIR) return EntryKind::Directory;
  if (type == DT_REG) return EntryKind::File;
  if (type == DT_LNK && stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) {
    return EntryKind::File;
  }
  return EntryKind::Other;
}

// Adds the program files directly in the directory `prefix` (its path as printed, ending in
// '/') to `files` and its subdirectories (ending in '/') to `subdirectories`. A directory that
// cannot be read is skipped, as by `find`. POSIX readdir, not std::filesystem: its iterator
// parses every path it builds into components, most of a walk's time.
void ListDirectory(const std::string& prefix, std::vector<std::string>* files,
                   std::vector<std::string>* subdirectories) {
  DIR* dir = opendir(prefix.c_str());
  if (dir == nullptr) return;
  while (const dirent* entry = readdir(dir)) {
    const std::string_view name = entry->d_name;
    if (name == "." || name == "..") continue;
    std::string path = prefix;
    path += name;
    switch (KindOf(*entry, path)) {
      case EntryKind::Directory:
        path += '/';
        subdirectories->push_back(std::move(path));
        break;
      case EntryKind::File:
        if (IsProgramFile(path)) files->push_back(std::move(path));
        break;
      case EntryKind::Other:
        break;
    }
  }
  closedir(dir);
}

// The program files anywhere under the directory `prefix`, sorted, as found inputs.
std::vector<Input> WalkDirectory(const std::string& prefix) {
  std::vector<std::string> files;
  std::vector<std::string> pending{prefix};
  while (!pending.empty()) {
    const std::string dir = std::move(pending.back());
    pending.pop_back();
    ListDirectory(dir, &files, &pending);
  }
  std::sort(files.begin(), files.end());
  std::vector<Input> found;
  found.reserve(files.size());
  for (std::string& path : files) {
    std::string display = path;
    found.push_back({std::move(path), std::move(display), {}, true, {}});
  }
  return found;
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
  // A directory's own entries are listed there too, and its subdirectories walked after,
  // also on the -j threads, each sorted where it was walked.
  std::vector<Input> named(args.size());
  std::vector<char> directory(args.size(), 0);
  std::vector<std::vector<std::string>> files(args.size());
  std::vector<std::vector<std::string>> subdirectories(args.size());
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
    // Found paths are printed as std::filesystem's generic form of `arg / name` (repeated
    // slashes made one).
    std::string prefix = (std::filesystem::path(arg) / "x").generic_string();
    prefix.pop_back();
    ListDirectory(prefix, &files[i], &subdirectories[i]);
    std::sort(files[i].begin(), files[i].end());
  });
  std::vector<std::pair<size_t, const std::string*>> walks;
  for (size_t i = 0; i < args.size(); ++i) {
    for (const std::string& sub : subdirectories[i]) walks.emplace_back(i, &sub);
  }
  std::vector<std::vector<Input>> walked(walks.size());
  ParallelFor(walks.size(), threads,
              [&](size_t w) { walked[w] = WalkDirectory(*walks[w].second); });

  std::vector<Input> inputs;
  inputs.reserve(args.size());
  size_t w = 0;
  for (size_t i = 0; i < args.size(); ++i) {
    if (!directory[i]) {
      inputs.push_back(std::move(named[i]));
      continue;
    }
    // Each subdirectory's files are sorted and follow one another in the sorted whole (they
    // alone start with its path), so the pieces are placed by their first path.
    std::vector<std::vector<Input>*> pieces;
    for (; w < walks.size() && walks[w].first == i; ++w) {
      if (!walked[w].empty()) pieces.push_back(&walked[w]);
    }
    std::sort(pieces.begin(), pieces.end(),
              [](const std::vector<Input>* a, const std::vector<Input>* b) {
                return a->front().path < b->front().path;
              });
    const size_t before = inputs.size();
    size_t f = 0;
    auto add_files_before = [&](const std::string* bound) {
      for (; f < files[i].size() && (bound == nullptr || files[i][f] < *bound); ++f) {
        inputs.push_back({files[i][f], std::move(files[i][f]), {}, true, {}});
      }
    };
    for (std::vector<Input>* piece : pieces) {
      add_files_before(&piece->front().path);
      for (Input& input : *piece) inputs.push_back(std::move(input));
    }
    add_files_before(nullptr);
    if (inputs.size() == before) {
      inputs.push_back({args[i],
                        args[i],
                        "no program files (.vp .fp .arbvp .arbfp, .txt with an ARB header) under "
                        "this directory",
                        false,
                        {}});
    }
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
  AddFormatOption(app, &options->format,
                  diagnostics ? std::vector<std::string>{"text", "json", "sarif"}
                              : std::vector<std::string>{"text", "json"});
  AddColorOption(app, &options->color);
  AddLimitsOption(app, &options->limits);
  AddStageOption(app, &options->stage, /*glsl=*/true);
  if (diagnostics) {
    AddErrorLimitOption(app, &options->error_limit);
    AddWerrorFlag(app, &options->werror);
    AddJobsOption(app, &options->jobs, "worker threads");
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
