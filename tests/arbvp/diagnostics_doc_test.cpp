// docs/diagnostics.md is generated from the diagnostics table (diagnostics.def) and the
// corpus: every code, its severity, summary and spec clause, and a corpus program that
// triggers it with arbiter's real output. This test regenerates it and compares;
// ARBITER_UPDATE_GOLDEN=1 rewrites the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "arbiter/arbvp/check.h"
#include "arbiter/compiler/render.h"

namespace arbiter::arbvp {
namespace {

namespace fs = std::filesystem;

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The first corpus program (in path order) whose checking reports `code`, per code.
std::map<std::string, std::string> Examples() {
  std::vector<std::string> names;
  fs::path root = fs::path(ARBITER_SOURCE_DIR) / "corpus" / "arb";
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".vp" || ext == ".fp")) {
      names.push_back(fs::relative(entry.path(), root).generic_string());
    }
  }
  std::sort(names.begin(), names.end());
  std::map<std::string, std::string> examples;
  for (const std::string& name : names) {
    std::string text = ReadAll(root / name);
    if (text.size() > 1500) continue;  // keep the page readable
    compiler::SourceFile source(name, text);
    compiler::DiagnosticSink sink(0);
    CheckProgram(source, CheckOptions{}, &sink);
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
      "Every diagnostic arbiter reports for ARB programs, generated from the table in\n"
      "`arbvp/src/diagnostics.def` by `tests/arbvp/diagnostics_doc_test.cpp` (run it with\n"
      "`ARBITER_UPDATE_GOLDEN=1` to regenerate). Codes are stable: a code never changes\n"
      "meaning. Each entry shows a program from `corpus/arb/` that triggers it and\n"
      "`arbiter check`'s output for it.\n\n"
      "Severities: an *error* rejects the program (exit code 1); a *warning* does not, unless\n"
      "`-Werror` is given. Limit checks (`arb-limit-*`, `arb-binding-index-range`) depend on the\n"
      "profile: without `--limits`, exceeding the spec minimum is the warning\n"
      "`arb-limit-portability` and exceeding what Mesa supports is an error; with `--limits\n"
      "PROFILE`, exceeding the profile is an error.\n\n"
      "## io-read\n\n"
      "**error**: an input could not be read (missing file, permission, a directory without\n"
      "programs). Exit code 3.\n\n";
  for (const compiler::DiagnosticInfo* info : AllDiagnostics()) {
    out += "## " + std::string(info->code) + "\n\n";
    out += "**" + std::string(compiler::SeverityName(info->severity)) +
           "**: " + std::string(info->summary) + ".";
    if (!info->spec_ref.empty()) out += " Spec: " + std::string(info->spec_ref) + ".";
    out += "\n\n";
    auto it = examples.find(std::string(info->code));
    if (it == examples.end()) {
      out += "No corpus program triggers it.\n\n";
      continue;
    }
    std::string text = ReadAll(fs::path(ARBITER_SOURCE_DIR) / "corpus" / "arb" / it->second);
    compiler::SourceFile source("corpus/arb/" + it->second, text);
    compiler::DiagnosticSink sink(0);
    CheckProgram(source, CheckOptions{}, &sink);
    compiler::FileReport report;
    report.path = source.path();
    for (const compiler::Diagnostic& d : sink.diagnostics()) {
      if (d.info->code == info->code) {
        report.diagnostics.push_back(d);
        break;
      }
    }
    out += "Example, `corpus/arb/" + it->second + "`:\n\n```\n" + text;
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
  for (const compiler::DiagnosticInfo* info : AllDiagnostics()) {
    EXPECT_TRUE(seen.insert(info->code).second) << info->code;
    EXPECT_EQ(info->code.substr(0, 4), "arb-") << info->code;
    for (char c : info->code)
      EXPECT_TRUE(std::islower(c) || std::isdigit(c) || c == '-') << info->code;
    EXPECT_FALSE(info->summary.empty());
    EXPECT_NE(info->summary.back(), '.') << info->code << ": summaries end without a period";
  }
}

}  // namespace
}  // namespace arbiter::arbvp
