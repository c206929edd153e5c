// Runs every corpus/arb program through the checker, with LF and CRLF line ends, and
// compares the verdict and every expected diagnostic (code and position) with the file's
// `# FAIL` / `# EXPECT-ERROR: line:col code` / `# EXPECT-WARNING: ...` comments.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "arbiter/arbvp/check.h"

namespace arbiter::arbvp {
namespace {

namespace fs = std::filesystem;

using Expectation = std::tuple<uint32_t, uint32_t, std::string>;  // line, column, code

std::vector<std::string> CorpusFiles() {
  std::vector<std::string> files;
  fs::path root = fs::path(ARBITER_SOURCE_DIR) / "corpus" / "arb";
  if (!fs::exists(root)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() &&
        (ext == ".vp" || ext == ".fp" || ext == ".arbvp" || ext == ".arbfp")) {
      files.push_back(fs::relative(entry.path(), root).generic_string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::set<Expectation> Expectations(const std::string& text, const std::string& tag) {
  std::set<Expectation> out;
  std::regex re("# " + tag + ": *([0-9]+):([0-9]+) +([a-z0-9-]+)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator();
       ++it) {
    out.emplace(std::stoul((*it)[1]), std::stoul((*it)[2]), (*it)[3]);
  }
  return out;
}

std::string ToCrlf(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\n') out += '\r';
    out += c;
  }
  return out;
}

std::string Describe(const std::set<Expectation>& set) {
  std::string out;
  for (const auto& [line, col, code] : set) {
    out += "  " + std::to_string(line) + ":" + std::to_string(col) + " " + code + "\n";
  }
  return out.empty() ? "  (none)\n" : out;
}

class CorpusTest : public ::testing::TestWithParam<std::string> {};

void CheckOne(const std::string& name, const std::string& text, const char* line_ends) {
  SCOPED_TRACE(std::string(name) + " with " + line_ends + " line ends");
  bool fail = text.find("# FAIL") != std::string::npos;
  std::set<Expectation> expected_errors = Expectations(text, "EXPECT-ERROR");
  std::set<Expectation> expected_warnings = Expectations(text, "EXPECT-WARNING");

  compiler::SourceFile source(name, text);
  compiler::DiagnosticSink sink(0);
  CheckResult result = CheckProgram(source, CheckOptions{}, &sink);
  std::set<Expectation> errors;
  std::set<Expectation> warnings;
  std::string all;
  for (const compiler::Diagnostic& d : sink.diagnostics()) {
    compiler::LineCol lc = source.Locate(d.range.begin);
    Expectation e{lc.line, lc.column, std::string(d.info->code)};
    (d.severity == compiler::Severity::Error ? errors : warnings).insert(e);
    all += "  " + std::to_string(lc.line) + ":" + std::to_string(lc.column) + " " +
           std::string(d.info->code) + ": " + d.message + "\n";
  }
  if (fail) {
    EXPECT_FALSE(result.ok) << "expected the program to be rejected";
    EXPECT_FALSE(expected_errors.empty()) << "a # FAIL program must list # EXPECT-ERROR lines";
    EXPECT_EQ(errors, expected_errors) << "expected errors:\n"
                                       << Describe(expected_errors) << "reported:\n"
                                       << all;
  } else {
    EXPECT_TRUE(result.ok) << "expected the program to be accepted; reported:\n" << all;
    EXPECT_TRUE(expected_errors.empty()) << "EXPECT-ERROR without # FAIL";
  }
  for (const Expectation& w : expected_warnings) {
    EXPECT_TRUE(warnings.count(w)) << "missing expected warning " << std::get<0>(w) << ":"
                                   << std::get<1>(w) << " " << std::get<2>(w) << "; reported:\n"
                                   << all;
  }
}

TEST_P(CorpusTest, VerdictAndDiagnostics) {
  fs::path path = fs::path(ARBITER_SOURCE_DIR) / "corpus" / "arb" / GetParam();
  std::string text = ReadAll(path);
  ASSERT_FALSE(text.empty()) << path;
  CheckOne(GetParam(), text, "LF");
  CheckOne(GetParam(), ToCrlf(text), "CRLF");
}

std::string TestName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name;
  for (char c : info.param) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusTest, ::testing::ValuesIn(CorpusFiles()), TestName);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(CorpusTest);

// The floor: at least 120 valid and 180 invalid programs, every invalid one marked.
TEST(Corpus, Size) {
  int valid = 0;
  int invalid = 0;
  for (const std::string& name : CorpusFiles()) {
    std::string text = ReadAll(fs::path(ARBITER_SOURCE_DIR) / "corpus" / "arb" / name);
    bool fail = text.find("# FAIL") != std::string::npos;
    (fail ? invalid : valid)++;
    EXPECT_EQ(fail, name.rfind("invalid/", 0) == 0) << name << ": # FAIL must match its folder";
  }
  EXPECT_GE(valid, 120);
  EXPECT_GE(invalid, 180);
}

}  // namespace
}  // namespace arbiter::arbvp
