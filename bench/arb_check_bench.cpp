// Throughput of the ARB front end, stage by stage: lexing only (BM_Lex*), lexing and parsing
// (BM_Parse*), and parsing and checking (BM_Check*, what `arbiter check` does), over the
// whole corpus, over its valid programs alone (what a build pipeline mostly checks) and over
// one large program.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/arbvp/check.h"
#include "lexer.h"  // arbvp/src: the stages on their own
#include "parser.h"

namespace {

namespace fs = std::filesystem;

// The programs under corpus/arb/<subdir> (all of corpus/arb when subdir is empty).
std::vector<std::string> LoadCorpus(std::string_view subdir = {}) {
  std::vector<std::string> texts;
  fs::path root = fs::path(ARBITER_SOURCE_DIR) / "corpus" / "arb" / subdir;
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

int64_t TotalBytes(const std::vector<std::string>& texts) {
  int64_t bytes = 0;
  for (const std::string& t : texts) bytes += static_cast<int64_t>(t.size());
  return bytes;
}

void SetCounters(benchmark::State& state, const std::vector<std::string>& texts) {
  state.SetBytesProcessed(state.iterations() * TotalBytes(texts));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(texts.size()));
  state.counters["programs"] = static_cast<double>(texts.size());
}

// The stages below the header: what Lex and ParseProgram start from.
constexpr uint32_t kHeaderSize = 10;  // "!!ARBvp1.0", "!!ARBfp1.0"

// The programs with a usable header, and their kind (the others stop at the header).
struct Headed {
  std::vector<std::string> texts;
  std::vector<arbiter::arbvp::ProgramKind> kinds;
};
Headed WithHeader(const std::vector<std::string>& texts) {
  Headed out;
  for (const std::string& t : texts) {
    std::string_view header = std::string_view(t).substr(0, kHeaderSize);
    if (header != "!!ARBvp1.0" && header != "!!ARBfp1.0") continue;
    out.texts.push_back(t);
    out.kinds.push_back(header == "!!ARBvp1.0" ? arbiter::arbvp::ProgramKind::Vertex
                                               : arbiter::arbvp::ProgramKind::Fragment);
  }
  return out;
}

void LexAll(benchmark::State& state, const Headed& programs) {
  for (auto _ : state) {
    for (const std::string& t : programs.texts) {
      arbiter::compiler::SourceFile source("bench", t);
      arbiter::compiler::DiagnosticSink sink(20);
      arbiter::arbvp::Lexer lexer(source, kHeaderSize, &sink);
      int tokens = 0;
      while (lexer.Next().kind != arbiter::arbvp::Tok::Eof) ++tokens;
      benchmark::DoNotOptimize(tokens);
    }
  }
  SetCounters(state, programs.texts);
}

void ParseAll(benchmark::State& state, const Headed& programs) {
  for (auto _ : state) {
    for (size_t i = 0; i < programs.texts.size(); ++i) {
      arbiter::compiler::SourceFile source("bench", programs.texts[i]);
      arbiter::compiler::DiagnosticSink sink(20);
      auto program =
          arbiter::arbvp::ParseProgram(source, programs.kinds[i], {0, kHeaderSize}, &sink);
      benchmark::DoNotOptimize(program.get());
    }
  }
  SetCounters(state, programs.texts);
}

void CheckAll(benchmark::State& state, const std::vector<std::string>& texts) {
  arbiter::arbvp::CheckOptions options;
  for (auto _ : state) {
    for (const std::string& t : texts) {
      arbiter::compiler::SourceFile source("bench", t);
      arbiter::compiler::DiagnosticSink sink(20);
      auto result = arbiter::arbvp::CheckProgram(source, options, &sink);
      benchmark::DoNotOptimize(result.ok);
    }
  }
  SetCounters(state, texts);
}

const std::vector<std::string>& Corpus() {
  static const std::vector<std::string> corpus = LoadCorpus();
  return corpus;
}
const std::vector<std::string>& ValidCorpus() {
  static const std::vector<std::string> valid = LoadCorpus("valid");
  return valid;
}
const std::vector<std::string>& Large() {
  static const std::vector<std::string> large = {LargeProgram()};
  return large;
}

void BM_LexCorpus(benchmark::State& state) {
  static const Headed programs = WithHeader(Corpus());
  LexAll(state, programs);
}
BENCHMARK(BM_LexCorpus)->Unit(benchmark::kMillisecond);

void BM_ParseCorpus(benchmark::State& state) {
  static const Headed programs = WithHeader(Corpus());
  ParseAll(state, programs);
}
BENCHMARK(BM_ParseCorpus)->Unit(benchmark::kMillisecond);

void BM_CheckCorpus(benchmark::State& state) { CheckAll(state, Corpus()); }
BENCHMARK(BM_CheckCorpus)->Unit(benchmark::kMillisecond);

void BM_CheckValidCorpus(benchmark::State& state) { CheckAll(state, ValidCorpus()); }
BENCHMARK(BM_CheckValidCorpus)->Unit(benchmark::kMillisecond);

void BM_LexLargeProgram(benchmark::State& state) {
  static const Headed programs = WithHeader(Large());
  LexAll(state, programs);
}
BENCHMARK(BM_LexLargeProgram)->Unit(benchmark::kMillisecond);

void BM_ParseLargeProgram(benchmark::State& state) {
  static const Headed programs = WithHeader(Large());
  ParseAll(state, programs);
}
BENCHMARK(BM_ParseLargeProgram)->Unit(benchmark::kMillisecond);

void BM_CheckLargeProgram(benchmark::State& state) { CheckAll(state, Large()); }
BENCHMARK(BM_CheckLargeProgram)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
