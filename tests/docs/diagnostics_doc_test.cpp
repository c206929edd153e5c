// docs/diagnostics.md is generated from the diagnostic tables (arbvp/src/diagnostics.def,
// glsl/src/diagnostics.def) and the corpora: every code, its severity, summary and spec
// clause, and a corpus program (or golden test input) that triggers it with arbiter's real
// output. This test regenerates it and compares;
// ARBITER_UPDATE_GOLDEN=1 rewrites the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include "arbiter/arbvp/check.h"
#include "arbiter/compiler/render.h"
#include "arbiter/glsl/check.h"

namespace arbiter::arbvp {
namespace {

namespace fs = std::filesystem;

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Runs the right checker on one file (by its extension) into `sink`, honouring the
// `ARGS: --limits NAME` / `--stage arbvp|arbfp` comment of golden inputs.
void CheckFile(const compiler::SourceFile& source, compiler::DiagnosticSink* sink) {
  if (std::optional<glsl::Stage> stage = glsl::StageFromPath(source.path())) {
    glsl::CheckShader(*stage, {&source}, glsl::CheckOptions{}, sink);
    return;
  }
  CheckOptions options;
  const std::string& text = source.text();
  size_t args = text.find("ARGS:");
  if (args != std::string::npos) {
    std::string line = text.substr(args, text.find_first_of("\r\n", args) - args);
    size_t limits = line.find("--limits ");
    if (limits != std::string::npos) {
      std::string name = line.substr(limits + 9);
      name = name.substr(0, name.find(' '));
      options.profile = compiler::BuiltinProfile(name);
    }
    if (line.find("--stage arbvp") != std::string::npos)
      options.expected_kind = ProgramKind::Vertex;
    if (line.find("--stage arbfp") != std::string::npos)
      options.expected_kind = ProgramKind::Fragment;
  }
  CheckProgram(source, options, sink);
}

// Example inputs, in this order: the ARB corpus, the GLSL corpus, the golden CLI inputs.
std::vector<std::string> ExampleFiles() {
  std::vector<std::string> names;
  for (const char* dir : {"corpus/arb", "corpus/glsl", "tests/golden/check"}) {
    fs::path root = fs::path(ARBITER_SOURCE_DIR) / dir;
    if (!fs::exists(root)) continue;
    std::vector<std::string> found;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      std::string ext = entry.path().extension().string();
      if (entry.is_regular_file() &&
          (ext == ".vp" || ext == ".fp" || ext == ".vert" || ext == ".frag")) {
        found.push_back(fs::relative(entry.path(), ARBITER_SOURCE_DIR).generic_string());
      }
    }
    std::sort(found.begin(), found.end());
    names.insert(names.end(), found.begin(), found.end());
  }
  return names;
}

// The first example file whose checking reports each code.
std::map<std::string, std::string> Examples() {
  std::map<std::string, std::string> examples;
  for (const std::string& name : ExampleFiles()) {
    std::string text = ReadAll(fs::path(ARBITER_SOURCE_DIR) / name);
    if (text.size() > 1500) continue;  // keep the page readable
    compiler::SourceFile source(name, text);
    compiler::DiagnosticSink sink(0);
    CheckFile(source, &sink);
    for (const compiler::Diagnostic& d : sink.diagnostics()) {
      examples.emplace(std::string(d.info->code), name);
    }
  }
  return examples;
}

std::string Generate() {
  std::map<std::string, std::string> examples = Examples();
  std::string out =
      "# arbiter diagnostics\n\n"
      "Every diagnostic arbiter reports, generated from the tables in\n"
      "`arbvp/src/diagnostics.def` (ARB programs) and `glsl/src/diagnostics.def` (GLSL 1.10) by\n"
      "`tests/docs/diagnostics_doc_test.cpp` (run it with `ARBITER_UPDATE_GOLDEN=1` to\n"
      "regenerate). Codes are stable: a code never changes meaning. Each entry shows an input\n"
      "from `corpus/` or `tests/golden/check/` that triggers it and `arbiter check`'s output\n"
      "for it.\n\n"
      "Severities: an *error* rejects the program (exit code 1); a *warning* does not, unless\n"
      "`-Werror` is given. Limit checks (`arb-limit-*`, `arb-binding-index-range`) depend on the\n"
      "profile: without `--limits`, exceeding the spec minimum is the warning\n"
      "`arb-limit-portability` and exceeding what Mesa supports is an error; with `--limits\n"
      "PROFILE`, exceeding the profile is an error.\n\n"
      "## io-read\n\n"
      "**error**: an input could not be read (missing file, permission, a directory without\n"
      "programs). Exit code 3.\n\n"
      "## driver-check-differs\n\n"
      "**note**: with `--driver-check`, Mesa's verdict on a GLSL shader differs from arbiter's;\n"
      "the note gives both verdicts and Mesa's first error line. It never changes the exit\n"
      "code. Where Mesa departs from GLSL 1.10 is listed in `docs/glsl-disagreements.md`.\n\n"
      "## runtime-gl-error\n\n"
      "**error**: a GL call failed while Mesa checked a shader for `--driver-check`. Exit code "
      "3.\n\n";
  std::vector<const compiler::DiagnosticInfo*> infos = AllDiagnostics();
  const auto& glsl_infos = glsl::AllDiagnostics();
  infos.insert(infos.end(), glsl_infos.begin(), glsl_infos.end());
  for (const compiler::DiagnosticInfo* info : infos) {
    out += "## " + std::string(info->code) + "\n\n";
    out += "**" + std::string(compiler::SeverityName(info->severity)) +
           "**: " + std::string(info->summary) + ".";
    if (!info->spec_ref.empty()) out += " Spec: " + std::string(info->spec_ref) + ".";
    out += "\n\n";
    auto it = examples.find(std::string(info->code));
    if (it == examples.end()) {
      out += "No example input triggers it yet.\n\n";
      continue;
    }
    std::string text = ReadAll(fs::path(ARBITER_SOURCE_DIR) / it->second);
    compiler::SourceFile source(it->second, text);
    compiler::DiagnosticSink sink(0);
    CheckFile(source, &sink);
    compiler::FileReport report;
    report.path = source.path();
    for (const compiler::Diagnostic& d : sink.diagnostics()) {
      if (d.info->code == info->code) {
        report.diagnostics.push_back(d);
        break;
      }
    }
    out += "Example, `" + it->second + "`:\n\n```\n" + text;
    if (!text.empty() && text.back() != '\n') out += "\n";
    out += "```\n\n```\n" + compiler::RenderText(report, compiler::TextOptions{}) + "```\n\n";
  }
  return out;
}

TEST(DiagnosticsDoc, MatchesTheTable) {
  fs::path doc = fs::path(ARBITER_SOURCE_DIR) / "docs" / "diagnostics.md";
  std::string expected = Generate();
  if (std::getenv("ARBITER_UPDATE_GOLDEN")) {
    std::ofstream(doc, std::ios::binary) << expected;
  }
  EXPECT_EQ(ReadAll(doc), expected)
      << "docs/diagnostics.md is out of date: rerun with ARBITER_UPDATE_GOLDEN=1";
}

TEST(DiagnosticsDoc, EveryCodeIsUniqueAndKebabCase) {
  std::set<std::string_view> seen;
  std::vector<const compiler::DiagnosticInfo*> infos = AllDiagnostics();
  const auto& glsl_infos = glsl::AllDiagnostics();
  infos.insert(infos.end(), glsl_infos.begin(), glsl_infos.end());
  for (const compiler::DiagnosticInfo* info : infos) {
    EXPECT_TRUE(seen.insert(info->code).second) << info->code;
    EXPECT_TRUE(info->code.substr(0, 4) == "arb-" || info->code.substr(0, 5) == "glsl-")
        << info->code;
    for (char c : info->code)
      EXPECT_TRUE(std::islower(c) || std::isdigit(c) || c == '-') << info->code;
    EXPECT_FALSE(info->summary.empty());
    EXPECT_NE(info->summary.back(), '.') << info->code << ": summaries end without a period";
  }
}

}  // namespace
}  // namespace arbiter::arbvp
