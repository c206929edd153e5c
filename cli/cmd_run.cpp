// arbiter run: piglit-format shader tests (.shader_test) on Mesa, PASS / FAIL / SKIP per
// test, with JUnit XML and PNG pictures on request.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "arbiter/arbvp/emit.h"
#include "arbiter/compiler/source.h"
#include "arbiter/runtime/shader_test.h"
#include "cli.h"
#include "options.h"

namespace arbiter::cli {
namespace {

namespace fs = std::filesystem;

struct RunCommandOptions {
  std::vector<std::string> files;
  std::string translate;  // "": run ARB programs as ARB; else the translation's target
  MesaOptions mesa;
  int jobs = 0;
  std::string format = "text";
  std::string junit;
  std::string png;
};

// The tests of the arguments: files as given, directories searched (recursively, sorted)
// for *.shader_test. `names` gets each test's PNG name: its path under the directory given,
// or its file name, with .png for .shader_test. False when an argument does not exist or a
// directory holds no test.
bool ExpandTests(const std::vector<std::string>& args, std::vector<std::string>* paths,
                 std::vector<std::string>* names) {
  bool ok = true;
  for (const std::string& arg : args) {
    std::error_code ec;
    auto png_name = [](fs::path relative) { return relative.replace_extension(".png").string(); };
    if (fs::is_directory(arg, ec)) {
      std::vector<fs::path> found;
      for (fs::recursive_directory_iterator it(arg, ec), end; !ec && it != end; it.increment(ec)) {
        if (it->is_regular_file(ec) && it->path().extension() == ".shader_test") {
          found.push_back(it->path());
        }
      }
      std::sort(found.begin(), found.end());
      if (found.empty()) {
        fmt::print(stderr, "arbiter: error: {}: no .shader_test files\n", arg);
        ok = false;
      }
      for (const fs::path& p : found) {
        paths->push_back(p.string());
        names->push_back(png_name(p.lexically_relative(arg)));
      }
    } else {
      // Missing and unreadable files fail as tests, with their reason.
      paths->push_back(arg);
      names->push_back(png_name(fs::path(arg).filename()));
    }
  }
  return ok;
}

// The lines of a result's message (which holds one line per failing probe or error).
std::vector<std::string> MessageLines(const std::string& message) {
  std::vector<std::string> lines;
  size_t pos = 0;
  while (pos < message.size()) {
    size_t end = message.find('\n', pos);
    if (end == std::string::npos) end = message.size();
    lines.push_back(message.substr(pos, end - pos));
    pos = end + 1;
  }
  return lines;
}

void PrintResult(const runtime::ShaderTestResult& r) {
  std::string out;
  const std::string_view status = runtime::TestStatusName(r.status);
  if (r.status == runtime::TestStatus::Pass) {
    out = fmt::format("PASS {}\n", r.path);
  } else {
    out = fmt::format("{} {}\n", status, r.path);
    for (const std::string& line : MessageLines(r.message)) out += fmt::format("  {}\n", line);
    for (const std::string& d : r.diagnostics) out += fmt::format("  {}\n", d);
  }
  for (const std::string& w : r.warnings) out += fmt::format("  warning: {}\n", w);
  fmt::print("{}", out);
}

// One test in `--format json`: the text report's content, the message split into lines.
nlohmann::ordered_json ResultJson(const runtime::ShaderTestResult& r) {
  nlohmann::ordered_json j;
  j["file"] = r.path;
  j["status"] = std::string(runtime::TestStatusName(r.status));
  j["message"] = MessageLines(r.message);
  j["diagnostics"] = r.diagnostics;
  j["warnings"] = r.warnings;
  if (!r.png.empty()) j["png"] = r.png;
  return j;
}

int RunTests(const RunCommandOptions& options) {
  runtime::RunOptions run;
  if (!runtime::ParseBackend(options.mesa.backend, &run.exec.backend)) {
    return static_cast<int>(Exit::Usage);
  }
  run.exec.driver = options.mesa.driver;
  run.translate = !options.translate.empty();
  std::string title;  // the translation's dialect, in the count line
  if (run.translate) {
    // The GLSL targets a GL or GL ES context runs; vk450 (and spirv, hlsl, msl) need Vulkan,
    // Direct3D or Metal.
    if (!arbvp::LookupEmitTarget(options.translate, &run.emit.target) ||
        run.emit.target == arbvp::EmitTarget::Vk450) {
      fmt::print(stderr,
                 "arbiter: error: --translate={}: run translates to glsl110, glsl120, glsl330, "
                 "es100 or es300\n",
                 options.translate);
      return static_cast<int>(Exit::Usage);
    }
    if (arbvp::UsesStateUniforms(run.emit)) run.emit.state = arbvp::StateSource::Uniforms;
    title = std::string(arbvp::EmitTargetTitle(run.emit.target));
  }
  run.jobs = options.jobs > 0 ? options.jobs
                              : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  run.limits.timeout_ms = options.mesa.timeout_ms;
  run.limits.memory_bytes = static_cast<uint64_t>(options.mesa.memory_mib) << 20;
  std::vector<std::string> paths;
  Exit exit = ExpandTests(options.files, &paths, &run.png_names) ? Exit::Ok : Exit::Rejected;
  if (!options.png.empty()) {
    // Two tests of one PNG name would overwrite each other's picture, the last to finish
    // winning (-j): refuse, as translate refuses two inputs with one output.
    std::set<std::string> seen;
    for (const std::string& name : run.png_names) {
      if (!seen.insert(name).second) {
        fmt::print(stderr, "arbiter: error: two tests would both write '{}' in '{}'\n", name,
                   options.png);
        return static_cast<int>(Exit::Usage);
      }
    }
    std::error_code ec;
    fs::create_directories(options.png, ec);
    if (ec) {
      fmt::print(stderr, "arbiter: error: {}: {}\n", options.png, ec.message());
      return static_cast<int>(Exit::Environment);
    }
    run.png_dir = options.png;
  }
  std::error_code ec;
  if (!options.junit.empty() && std::any_of(paths.begin(), paths.end(), [&](const std::string& p) {
        return fs::equivalent(p, options.junit, ec);
      })) {
    fmt::print(stderr, "arbiter: error: --junit {} would overwrite an input\n", options.junit);
    return static_cast<int>(Exit::Usage);
  }

  const std::vector<runtime::ShaderTestResult> results = runtime::RunShaderTests(paths, run);
  size_t passed = 0, failed = 0, skipped = 0;
  for (const runtime::ShaderTestResult& r : results) {
    passed += r.status == runtime::TestStatus::Pass ? 1 : 0;
    failed += r.status == runtime::TestStatus::Fail ? 1 : 0;
    skipped += r.status == runtime::TestStatus::Skip ? 1 : 0;
  }
  if (options.format == "json") {
    nlohmann::ordered_json j;
    j["driver"] = options.mesa.driver;
    j["backend"] = options.mesa.backend;
    j["translate"] = run.translate;
    if (run.translate) j["target"] = options.translate;
    nlohmann::ordered_json tests = nlohmann::ordered_json::array();
    for (const runtime::ShaderTestResult& r : results) tests.push_back(ResultJson(r));
    j["tests"] = std::move(tests);
    j["passed"] = passed;
    j["failed"] = failed;
    j["skipped"] = skipped;
    // A path that is not UTF-8 becomes U+FFFD instead of throwing.
    fmt::print("{}\n", j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
  } else {
    for (const runtime::ShaderTestResult& r : results) PrintResult(r);
    fmt::print("{} passed, {} failed, {} skipped ({} via {}{})\n", passed, failed, skipped,
               options.mesa.driver, options.mesa.backend,
               !run.translate                   ? ""
               : options.translate == "glsl110" ? ", ARB translated to GLSL"
                                                : ", ARB translated to " + title);
  }
  if (failed > 0) exit = Worse(exit, Exit::Rejected);
  for (const runtime::ShaderTestResult& r : results) {
    if (r.environment) exit = Worse(exit, Exit::Environment);
  }
  if (!options.junit.empty()) {
    std::string error;
    const std::string suite = !run.translate ? "arbiter run"
                              : options.translate == "glsl110"
                                  ? "arbiter run --translate"
                                  : "arbiter run --translate=" + options.translate;
    if (!compiler::WriteFileAtomically(options.junit, runtime::JunitXml(results, suite), &error)) {
      fmt::print(stderr, "arbiter: error: {}: {}\n", options.junit, error);
      exit = Worse(exit, Exit::Environment);
    }
  }
  return static_cast<int>(exit);
}

}  // namespace

// Adds the `run` subcommand to `app`; the returned function runs it once it is parsed.
std::function<int()> AddRunCommand(CLI::App* app) {
  auto options = std::make_shared<RunCommandOptions>();
  CLI::App* cmd = app->add_subcommand(
      "run", "run piglit-format shader tests (.shader_test) on Mesa: PASS, FAIL or SKIP each");
  cmd->footer(
      "Each test runs in a worker process with its own time and memory limit; a test that "
      "crashes or hangs fails alone. Exit 1 when a test fails. The format and arbiter's "
      "extensions: docs/run.md.");
  cmd->add_option("files", options->files, "shader tests (directories are searched)")->required();
  cmd->add_flag("--translate{glsl110}", options->translate,
                "run ARB programs as arbiter's translation to this target instead of Mesa's ARB "
                "path: glsl110 (default), glsl120, glsl330, es100, es300; the targets without "
                "built-in state get the GL state the test sets as uniforms");
  AddMesaOptions(cmd, &options->mesa, "per test");
  AddJobsOption(cmd, &options->jobs, "worker processes");
  AddFormatOption(cmd, &options->format, {"text", "json"});
  cmd->add_option("--junit", options->junit, "also write the results as JUnit XML to this file");
  cmd->add_option("--png", options->png, "save each test's picture as PNG under this folder");
  return [options] { return RunTests(*options); };
}

}  // namespace arbiter::cli
