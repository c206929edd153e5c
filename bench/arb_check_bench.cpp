// Parse+check throughput of the ARB front end: the whole corpus, and one large program.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "arbiter/arbvp/check.h"

namespace {

namespace fs = std::filesystem;

std::vector<std::string> LoadCorpus() {
  std::vector<std::string> texts;
  fs::path root = fs::path(ARBITER_SOURCE_DIR) / "corpus" / "arb";
  std::vector<fs::path> paths;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".vp" || ext == ".fp")) paths.push_back(entry.path());
  }
  std::sort(paths.begin(), paths.end());
  for (const fs::path& p : paths) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    texts.push_back(ss.str());
  }
  return texts;
}

// A realistic large vertex program: a skinning-like body repeated (valid, 4 000 lines).
std::string LargeProgram() {
  std::string text =
      "!!ARBvp1.0\nPARAM mvp[4] = { state.matrix.mvp };\nPARAM bones[64] = { "
      "program.env[0..63] };\nADDRESS a0;\nTEMP r0, r1, r2;\nATTRIB w = vertex.attrib[1];\n";
  for (int i = 0; i < 1000; ++i) {
    text +=
        "ARL a0.x, w.x;\nDP4 r0.x, bones[a0.x], vertex.position;\n"
        "MAD r1, r0.xxxx, {0.5, 0.25, 0.125, 1.0}, -r2;\n# comment line\n";
  }
  text +=
      "DP4 result.position.x, mvp[0], r1;\nDP4 result.position.y, mvp[1], r1;\n"
      "DP4 result.position.z, mvp[2], r1;\nDP4 result.position.w, mvp[3], r1;\nEND\n";
  return text;
}

void CheckAll(benchmark::State& state, const std::vector<std::string>& texts) {
  int64_t bytes = 0;
  for (const std::string& t : texts) bytes += static_cast<int64_t>(t.size());
  arbiter::arbvp::CheckOptions options;
  for (auto _ : state) {
    for (const std::string& t : texts) {
      arbiter::compiler::SourceFile source("bench", t);
      arbiter::compiler::DiagnosticSink sink(20);
      auto result = arbiter::arbvp::CheckProgram(source, options, &sink);
      benchmark::DoNotOptimize(result.ok);
    }
  }
  state.SetBytesProcessed(state.iterations() * bytes);
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(texts.size()));
  state.counters["programs"] = static_cast<double>(texts.size());
}

void BM_CheckCorpus(benchmark::State& state) {
  static const std::vector<std::string> corpus = LoadCorpus();
  CheckAll(state, corpus);
}
BENCHMARK(BM_CheckCorpus)->Unit(benchmark::kMillisecond);

void BM_CheckLargeProgram(benchmark::State& state) {
  static const std::vector<std::string> large = {LargeProgram()};
  CheckAll(state, large);
}
BENCHMARK(BM_CheckLargeProgram)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
