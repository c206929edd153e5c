// Runs every corpus/glsl shader through the GLSL checker and compares the verdict with its
// piglit `// [config]` block (formats.md): `expect_result: pass|fail`, and `check_link: true`
// to judge it as a linked program. Shaders where arbiter does not yet follow the
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

struct Config {
  std::map<std::string, std::string> values;
  std::string error;
};

// Parses the `[config]` comment block at the top (leaders //, /* or *).
Config ParseConfig(const std::string& text) {
  Config config;
  std::istringstream in(text);
  std::string line;
  bool inside = false;
  bool done = false;
  while (!done && std::getline(in, line)) {
    std::string s = line;
    s.erase(0, s.find_first_not_of(" \t"));
    for (const char* leader : {"//", "/*", "*"}) {
      if (s.rfind(leader, 0) == 0) {
        s.erase(0, std::string(leader).size());
        break;
      }
    }
    s.erase(0, s.find_first_not_of(" \t"));
    while (!s.empty() &&
           (s.back() == '\r' || s.back() == ' ' || s.back() == '/' || s.back() == '*')) {
      s.pop_back();
    }
    if (s == "[config]") {
      inside = true;
    } else if (s == "[end config]") {
      done = true;
    } else if (inside && !s.empty()) {
      size_t colon = s.find(':');
      if (colon == std::string::npos) {
        config.error = "config line without ':': " + s;
        continue;
      }
      std::string key = s.substr(0, colon);
      std::string value = s.substr(colon + 1);
      value.erase(0, value.find_first_not_of(" \t"));
      static const std::set<std::string> kKeys = {"expect_result", "glsl_version",
                                                  "require_extensions", "check_link"};
      if (!kKeys.count(key)) config.error = "unknown config key '" + key + "'";
      if (!config.values.emplace(key, value).second) config.error = "duplicate key '" + key + "'";
    }
  }
  if (!done) config.error = "no [config] ... [end config] block";
  return config;
}

class GlslCorpusTest : public ::testing::TestWithParam<std::string> {};

TEST_P(GlslCorpusTest, Verdict) {
  const std::string& name = GetParam();
  std::string text = ReadAll(CorpusRoot() / name);
  Config config = ParseConfig(text);
  ASSERT_TRUE(config.error.empty()) << name << ": " << config.error;
  ASSERT_TRUE(config.values.count("expect_result")) << name << ": no expect_result";
  std::string expect = config.values["expect_result"];
  ASSERT_TRUE(expect == "pass" || expect == "fail") << name << ": expect_result " << expect;

  compiler::SourceFile source(name, text);
  compiler::DiagnosticSink sink(0);
  CheckOptions options;
  bool link = config.values["check_link"] == "true";
  options.link = link;
  options.link_as_program = link;
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
