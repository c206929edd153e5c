// Runs every corpus/glsl shader through the GLSL checker and compares the verdict with its
// piglit `// [config]` block (docs/design/formats.md): `expect_result: pass|fail`, and `check_link:
// true` to judge it as a linked program. Shaders where arbiter does not yet follow the
// specification are listed, with the reason, in tests/glsl/known-gaps.txt: they must still
// disagree (a fixed gap must leave the list), and every other shader must agree.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "arbiter/glsl/check.h"
#include "arbiter/glsl/test_config.h"

namespace arbiter::glsl {
namespace {

namespace fs = std::filesystem;

fs::path CorpusRoot() { return fs::path(ARBITER_SOURCE_DIR) / "corpus" / "glsl"; }

std::vector<std::string> CorpusFiles() {
  std::vector<std::string> files;
  if (!fs::exists(CorpusRoot())) return files;
  for (const auto& entry : fs::recursive_directory_iterator(CorpusRoot())) {
    if (entry.is_regular_file() && StageFromPath(entry.path().string())) {
      files.push_back(fs::relative(entry.path(), CorpusRoot()).generic_string());
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

// The known gaps: "path  # reason" per line.
std::set<std::string> KnownGaps() {
  std::set<std::string> gaps;
  std::ifstream in(fs::path(ARBITER_SOURCE_DIR) / "tests" / "glsl" / "known-gaps.txt");
  std::string line;
  while (std::getline(in, line)) {
    size_t hash = line.find('#');
    std::string path = line.substr(0, hash);
    path.erase(path.find_last_not_of(" \t") + 1);
    if (!path.empty()) gaps.insert(path);
  }
  return gaps;
}

class GlslCorpusTest : public ::testing::TestWithParam<std::string> {};

TEST_P(GlslCorpusTest, Verdict) {
  const std::string& name = GetParam();
  std::string text = ReadAll(CorpusRoot() / name);
  ParserTestConfig config = ParseParserTestConfig(text);
  ASSERT_TRUE(config.error.empty()) << name << ": " << config.error;
  ASSERT_TRUE(config.values.count("expect_result")) << name << ": no expect_result";
  std::string expect = config.values["expect_result"];
  ASSERT_TRUE(expect == "pass" || expect == "fail") << name << ": expect_result " << expect;

  compiler::SourceFile source(name, text);
  compiler::DiagnosticSink sink(0);
  CheckOptions options;
  bool link = config.values["check_link"] == "true";
  options.link = link;
  CheckResult result = CheckShader(*StageFromPath(name), {&source}, options, &sink);
  std::string log;
  for (const compiler::Diagnostic& d : sink.diagnostics()) {
    compiler::LineCol lc = source.Locate(d.range.begin);
    log += "  " + std::to_string(lc.line) + ":" + std::to_string(lc.column) + " " +
           std::string(d.info->code) + ": " + d.message + "\n";
  }
  bool agrees = result.ok == (expect == "pass");
  if (KnownGaps().count(name)) {
    EXPECT_FALSE(agrees) << name << " is listed in tests/glsl/known-gaps.txt but arbiter now "
                         << "gives the expected verdict: remove it from the list";
  } else {
    EXPECT_TRUE(agrees) << name << ": expected " << expect << ", arbiter says "
                        << (result.ok ? "pass" : "fail") << "\n"
                        << log;
  }
}

std::string TestName(const ::testing::TestParamInfo<std::string>& info) {
  std::string out;
  for (char c : info.param) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return out;
}

INSTANTIATE_TEST_SUITE_P(Corpus, GlslCorpusTest, ::testing::ValuesIn(CorpusFiles()), TestName);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(GlslCorpusTest);

TEST(GlslCorpus, KnownGapsExist) {
  for (const std::string& gap : KnownGaps()) {
    EXPECT_TRUE(fs::exists(CorpusRoot() / gap)) << "known-gaps.txt lists a missing file " << gap;
  }
}

}  // namespace
}  // namespace arbiter::glsl
