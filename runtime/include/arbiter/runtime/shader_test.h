// piglit's shader_runner format (.shader_test; docs/design/formats.md): one file states a
// shader and what it must draw. ParseShaderTest reads the sections; RunShaderTests draws each
// test on Mesa (OSMesa or EGL, softpipe or llvmpipe) in worker processes and evaluates its
// probes with piglit's tolerance rules. docs/run.md describes the commands and extensions.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/arbvp/emit.h"
#include "arbiter/runtime/exec.h"
#include "arbiter/runtime/worker.h"

namespace arbiter::runtime {

// One line of a section, with its 1-based line number in the file.
struct ShaderTestLine {
  int line = 0;
  std::string text;
};

// A program or shader section's source.
struct ShaderTestSource {
  int line = 0;  // the line of the section header ("[vertex program]"); 0: absent
  std::string text;
};

struct ShaderTest {
  std::string path;
  std::vector<ShaderTestLine> require;
  ShaderTestSource vertex_program;    // [vertex program] (ARB)
  ShaderTestSource fragment_program;  // [fragment program] (ARB)
  // [vertex shader] / [fragment shader] (GLSL): a stage may have several shaders, which
  // are compiled apart and linked together.
  std::vector<ShaderTestSource> vertex_shaders;
  std::vector<ShaderTestSource> fragment_shaders;
  bool vertex_passthrough = false;  // [vertex shader passthrough]
  int passthrough_line = 0;
  std::vector<ShaderTestLine> vertex_data;  // [vertex data]: header then rows
  std::vector<ShaderTestLine> commands;     // [test], comments and blank lines removed
};

// Splits `text` into sections. On a malformed file (an unknown or repeated section, text in
// [vertex shader passthrough]) returns false with the line in `error_line` and the reason in
// `error`. Text before the first section is ignored, as piglit ignores it.
bool ParseShaderTest(std::string_view text, std::string path, ShaderTest* test, int* error_line,
                     std::string* error);

// The #version piglit's shader_runner gives a GLSL shader of `test` that has none: the one
// its [require] asks for ("GLSL >= 1.20" -> "#version 120\n"); "" for 1.10, the default.
std::string ShaderTestVersionDirective(const ShaderTest& test);

enum class TestStatus : uint8_t {
  Pass,
  Fail,  // a probe failed, a program was rejected, or the file is malformed
  Skip,  // a [require] is not met
};
std::string_view TestStatusName(TestStatus status);  // "PASS", "FAIL", "SKIP"

struct ShaderTestResult {
  std::string path;
  TestStatus status = TestStatus::Fail;
  // FAIL: the failing probe with expected and observed values, or the error, as
  // "file:line: ..." lines; SKIP: the unmet requirement.
  std::string message;
  // The programs' diagnostics (arbiter's, and Mesa's info log) when one was rejected.
  std::vector<std::string> diagnostics;
  std::vector<std::string> warnings;  // failed `probe warn` commands
  std::string png;                    // the picture written under png_dir, if any
  // The test could not run for a reason outside it: no GL context, a --png file that cannot
  // be written (the command exits 3 then).
  bool environment = false;
};

struct RunOptions {
  ExecOptions exec;
  // Runs each ARB program through arbiter's GLSL translation (TranslateChecked) instead of
  // Mesa's ARB path.
  bool translate = false;
  arbvp::EmitOptions emit;  // the translation --translate runs
  // Worker processes, each with one GL context reused for many tests.
  int jobs = 1;
  // Per test: a test that crashes, hangs or exhausts its worker fails alone.
  WorkerLimits limits;
  // When set, each test's final picture is saved as PNG under this folder, named after
  // `png_names` (same order as the paths), written atomically.
  std::string png_dir;
  std::vector<std::string> png_names;
};

// Runs every file of `paths` (already expanded; missing or unreadable files fail with their
// reason); results in input order whatever `jobs`.
std::vector<ShaderTestResult> RunShaderTests(const std::vector<std::string>& paths,
                                             const RunOptions& options);

// JUnit XML for CI systems: one <testcase> per result (no timings: the output is a pure
// function of the results).
std::string JunitXml(const std::vector<ShaderTestResult>& results, const std::string& suite);

// Writes RGBA8 pixels (bottom row first, as glReadPixels gives them) as a PNG, atomically.
bool WritePng(const std::string& path, int width, int height, const std::vector<uint8_t>& rgba,
              std::string* error);

}  // namespace arbiter::runtime
