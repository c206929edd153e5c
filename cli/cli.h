// Shared pieces of the arbiter command: inputs, options common to verbs, exit codes.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "arbiter/arbvp/ir.h"
#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/limits.h"
#include "arbiter/compiler/render.h"
#include "arbiter/compiler/source.h"
#include "arbiter/glsl/check.h"
#include "arbiter/glsl/link.h"

namespace arbiter::cli {

// Process exit codes (docs/design/architecture.md).
enum class Exit : int { Ok = 0, Rejected = 1, Usage = 2, Environment = 3 };

// The worse of two outcomes: Environment > Usage > Rejected > Ok.
Exit Worse(Exit a, Exit b);

// One input as given on the command line (a directory expands to the files under it).
struct Input {
  std::string path;          // as given, or as found under a given directory; "-" is stdin
  std::string display_path;  // "<stdin>" for "-"
  std::string error;   // set when the argument cannot give a program (unreadable, empty directory)
  bool found = false;  // found under a directory argument, not named
  // A named file is read while the arguments are expanded; ReadInput takes the bytes (and
  // reads the file again if asked twice).
  mutable std::optional<std::string> bytes;
};

// Expands files and directories (recursively, sorted; ARB and GLSL file extensions) and
// reads the files named early in the batch; `threads` as for ParallelFor. Unreadable paths
// are kept: ReadInput reports the error.
std::vector<Input> ExpandInputs(const std::vector<std::string>& args, size_t threads);

// Reads an input into a SourceFile (taking the bytes ExpandInputs read); on failure returns
// null and adds an `io-read` error to `report`.
std::unique_ptr<compiler::SourceFile> ReadInput(const Input& input, compiler::FileReport* report);

// --format, --color, --error-limit, -Werror, --limits, --stage shared by check and info.
struct CommonOptions {
  std::string format = "text";
  std::string color = "auto";
  int error_limit = 20;
  bool werror = false;
  std::string limits;
  std::string stage;
  int jobs = 0;  // -j: worker threads; 0 = the number of cores
  // --driver-check and --driver (cli/driver_check.h): `check` also asks Mesa.
  bool driver_check = false;
  std::string driver = "softpipe";
  std::vector<std::string> files;
  // GLSL: --link (the inputs are one program), -D, -U, -I, --preamble, and the warning
  // switches -W<code>, -Wno-<code>, -Werror=<code> (main.cpp passes them as --warning).
  bool link = false;
  std::vector<std::string> defines;
  std::vector<std::string> undefines;
  std::vector<std::string> include_dirs;
  std::string preamble;
  std::vector<std::string> warnings;
};

// What the GLSL options of CommonOptions resolve to: the preamble file read, the warning
// switches checked against the known codes.
struct GlslSetup {
  std::optional<compiler::LimitProfile> profile;
  std::unique_ptr<compiler::SourceFile> preamble;
  glsl::CheckOptions check;
  compiler::WarningPolicy warnings;
};
// Resolves --limits, the preprocessor options and the warning switches; on error prints it
// and returns the exit code (Usage, or Environment for an unreadable --preamble).
std::optional<Exit> ResolveGlslSetup(const CommonOptions& options, GlslSetup* out);
// Links GLSL shader objects as one program (glsl::LinkShaders) with the setup's options and
// warning switches, and moves the diagnostics to the reports of their files (keep[i] is
// reports[i]'s file). Returns Rejected when the program does not link.
Exit LinkAndReport(const std::vector<glsl::ShaderObject>& objects, const CommonOptions& options,
                   const GlslSetup& glsl_setup,
                   const std::vector<std::unique_ptr<compiler::SourceFile>>& keep,
                   std::vector<compiler::FileReport>* reports);
// Adds -D, -U, -I, --preamble and --warning to a command that checks GLSL.
void AddGlslOptions(CLI::App* app, CommonOptions* options);

// glibc's malloc gives memory back to the kernel and grows a thread's heap a few pages at a
// time; with two threads each such change also flushes the other core's TLB (an
// inter-processor interrupt, dear in a VM). For check, a batch process that exits when
// done, keeping what it got makes -j 2 7 % faster on ARB programs and 3 % on GLSL shaders.
// Not for verify and run: Mesa's large calloc()s would then be cleared by hand instead of
// coming as fresh pages (verify -j 2 took 1.28x as long). docs/performance.md.
void KeepMallocMemory();

// The number of worker threads -j asks for (0: one per core).
size_t ResolveJobs(const CommonOptions& options);
// Runs body(0) ... body(count - 1) on up to `threads` threads (the caller's among them),
// each index once; a body writes only its own index's result. The caller's thread works
// alone until the batch (from its ExpandInputs) has lasted 2 ms: short batches gain
// nothing from a second thread.
void ParallelFor(size_t count, size_t threads, const std::function<void(size_t)>& body);
void AddCommonOptions(CLI::App* app, CommonOptions* options, bool diagnostics);

// Resolves --limits; on error prints it and returns false.
bool ResolveLimits(const CommonOptions& options, std::optional<compiler::LimitProfile>* out);
// Resolves --stage for ARB inputs (arbvp/arbfp; nothing for vert/frag).
bool ResolveStage(const CommonOptions& options, std::optional<arbvp::ProgramKind>* out);
// The GLSL stage of an input: --stage vert/frag, else its extension; nullopt for ARB.
std::optional<glsl::Stage> GlslStage(const CommonOptions& options, const Input& input);

// Moves each diagnostic of `sink` to the report of the file it is in (reports[i] is keep[i]'s;
// a diagnostic of no file goes to the first); the first report gets the dropped count.
void DistributeDiagnostics(compiler::DiagnosticSink* sink,
                           const std::vector<std::unique_ptr<compiler::SourceFile>>& keep,
                           std::vector<compiler::FileReport>* reports);

// Prints the reports in the chosen format (text to stderr, json/sarif to stdout).
void PrintReports(const std::vector<compiler::FileReport>& reports, const CommonOptions& options);
// The diagnostics of `reports` as the "diagnostics" member of the JSON documents of info,
// exec and verify: the entries of check's "files" (docs/json-output.md).
nlohmann::ordered_json DiagnosticsJson(const std::vector<compiler::FileReport>& reports);
// The text renderer's options (--color, the terminal); and the printing of reports a batch
// has rendered as text in its workers, in order, in one write.
compiler::TextOptions TextOptionsFor(const CommonOptions& options);
void PrintText(const std::vector<std::string>& rendered);

int RunCheck(const CommonOptions& options);
int RunInfo(const CommonOptions& options);

}  // namespace arbiter::cli
