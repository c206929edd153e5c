// Translation and verification throughput over the valid ARB corpus: the emitter alone, the
// emitter with its glslang self-check (what `arbiter translate` does per program), and
// `arbiter verify`'s engine (inputs, interpreter, Mesa ARB and GLSL engines in one worker)
// on the driver named by ARBITER_BENCH_DRIVER (softpipe by default).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/emit.h"
#include "arbiter/compiler/source.h"
#include "arbiter/runtime/translate.h"
#include "arbiter/runtime/verify.h"

namespace {

using namespace arbiter;

struct Corpus {
  std::vector<std::unique_ptr<compiler::SourceFile>> sources;
  std::vector<std::unique_ptr<arbvp::Program>> programs;
};

const Corpus& ValidCorpus() {
  static const Corpus corpus = [] {
    Corpus c;
    std::vector<std::filesystem::path> paths;
    for (const auto& e :
         std::filesystem::directory_iterator(ARBITER_SOURCE_DIR "/corpus/arb/valid")) {
      paths.push_back(e.path());
    }
    std::sort(paths.begin(), paths.end());
    for (const auto& p : paths) {
      std::string text;
      std::string error;
      if (!compiler::ReadFileBytes(p.string(), &text, &error)) continue;
      auto source = std::make_unique<compiler::SourceFile>(p.string(), text);
      compiler::DiagnosticSink sink(0);
      arbvp::CheckResult r = arbvp::CheckProgram(*source, {}, &sink);
      if (!r.ok || !r.program) continue;
      c.sources.push_back(std::move(source));
      c.programs.push_back(std::move(r.program));
    }
    return c;
  }();
  return corpus;
}

std::string Driver() {
  const char* driver = std::getenv("ARBITER_BENCH_DRIVER");
  return driver ? driver : "softpipe";
}

void BM_EmitCorpus(benchmark::State& state) {
  const Corpus& c = ValidCorpus();
  for (auto _ : state) {
    for (const auto& p : c.programs) {
      benchmark::DoNotOptimize(arbvp::EmitGlsl(*p, arbvp::EmitOptions{}, nullptr).glsl.size());
    }
  }
  state.counters["programs/s"] = benchmark::Counter(static_cast<double>(c.programs.size()),
                                                    benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_EmitCorpus)->Unit(benchmark::kMillisecond);

void BM_TranslateCheckedCorpus(benchmark::State& state) {
  const Corpus& c = ValidCorpus();
  for (auto _ : state) {
    for (const auto& p : c.programs) {
      const bool vp = p->kind == arbvp::ProgramKind::Vertex;
      runtime::CheckedTranslation t = runtime::TranslateChecked(
          vp ? p.get() : nullptr, vp ? nullptr : p.get(), arbvp::EmitOptions{}, nullptr, nullptr);
      if (!t.ok) state.SkipWithError(t.error.c_str());
    }
  }
  state.counters["programs/s"] = benchmark::Counter(static_cast<double>(c.programs.size()),
                                                    benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_TranslateCheckedCorpus)->Unit(benchmark::kMillisecond);

// Verify of the first `range(0)` corpus programs with the default inputs (the edge batch and
// 64 random vectors).
void BM_VerifyCorpus(benchmark::State& state) {
  const Corpus& c = ValidCorpus();
  const size_t count = std::min(c.programs.size(), static_cast<size_t>(state.range(0)));
  std::vector<runtime::VerifySubject> subjects;
  for (size_t i = 0; i < count; ++i) {
    runtime::VerifySubject s;
    s.name = c.sources[i]->path();
    const bool vp = c.programs[i]->kind == arbvp::ProgramKind::Vertex;
    (vp ? s.vertex : s.fragment) = c.programs[i].get();
    subjects.push_back(s);
  }
  runtime::VerifyOptions options;
  options.exec.driver = Driver();
  for (auto _ : state) {
    std::vector<runtime::Verdict> verdicts = runtime::Verify(subjects, options);
    for (const runtime::Verdict& v : verdicts) {
      if (!v.error.empty() || !v.disagreements.empty()) state.SkipWithError(v.name.c_str());
    }
  }
  state.SetLabel(Driver());
  state.counters["programs/s"] =
      benchmark::Counter(static_cast<double>(count), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_VerifyCorpus)
    ->Arg(1)
    ->Arg(1000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
