// Execution throughput: vectors per second and the cost of a new program, on the reference
// interpreter and on Mesa (in process, one context; the driver from ARBITER_BENCH_DRIVER,
// the backend from ARBITER_BENCH_BACKEND, since OSMesa picks its driver once per process).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <memory>
#include <string>

#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/interpret.h"
#include "arbiter/runtime/exec.h"

namespace {

using namespace arbiter;

// A per-vertex lighting program of typical size (23 instructions): transform, normal,
// diffuse and specular terms with LIT, and a texture coordinate.
constexpr char kLighting[] = R"(!!ARBvp1.0
PARAM mvp[4] = { state.matrix.mvp };
PARAM mv[4] = { state.matrix.modelview.invtrans };
PARAM light = state.light[0].position;
PARAM half = state.light[0].half;
PARAM diffuse = state.lightprod[0].diffuse;
PARAM ambient = state.lightprod[0].ambient;
PARAM specular = state.lightprod[0].specular;
PARAM shine = state.material.shininess;
TEMP n, l, dots, lit, c;
DP4 result.position.x, mvp[0], vertex.position;
DP4 result.position.y, mvp[1], vertex.position;
DP4 result.position.z, mvp[2], vertex.position;
DP4 result.position.w, mvp[3], vertex.position;
DP3 n.x, mv[0], vertex.normal;
DP3 n.y, mv[1], vertex.normal;
DP3 n.z, mv[2], vertex.normal;
DP3 n.w, n, n;
RSQ n.w, n.w;
MUL n.xyz, n, n.w;
DP3 dots.x, n, light;
DP3 dots.y, n, half;
MOV dots.w, shine.x;
LIT lit, dots;
MAD c, lit.y, diffuse, ambient;
MAD result.color.xyz, lit.z, specular, c;
MOV result.color.w, diffuse.w;
MOV result.texcoord[0], vertex.texcoord[0];
END
)";

std::unique_ptr<arbvp::Program> Check(const std::string& text) {
  compiler::SourceFile source("bench.vp", text);
  compiler::DiagnosticSink sink(0);
  arbvp::CheckResult r = arbvp::CheckProgram(source, {}, &sink);
  return r.ok ? std::move(r.program) : nullptr;
}

arbvp::ExecInputs Inputs(size_t count) {
  arbvp::ExecInputs in;
  in.state.light[0].position = {0.3f, 0.5f, 0.8f, 0.0f};
  in.state.material[0].shininess = 16.0f;
  for (size_t i = 0; i < count; ++i) {
    arbvp::InputVector v;
    float t = static_cast<float>(i) / static_cast<float>(count);
    v.vertex.position = {t, 1.0f - t, 0.5f * t, 1.0f};
    v.vertex.normal = {1.0f - t, t, 0.25f, 0.0f};
    v.vertex.texcoord[0] = {t, t, 0.0f, 1.0f};
    in.vectors.push_back(v);
  }
  return in;
}

// A variant of the program that no cache can have seen: its constant differs per call.
std::string Variant(size_t n) {
  std::string text = kLighting;
  text.replace(text.find("MOV result.color.w, diffuse.w;"), 30,
               "ADD result.color.w, diffuse.w, " + std::to_string(n % 100000) + ".5;");
  return text;
}

void BM_RefVectors(benchmark::State& state) {
  auto program = Check(kLighting);
  arbvp::ExecInputs in = Inputs(static_cast<size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(arbvp::Interpret(*program, in));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_RefVectors)->Arg(1000)->Unit(benchmark::kMillisecond);

// Check + interpret one vector of a new program: what verify pays per program on `ref`.
void BM_RefNewProgram(benchmark::State& state) {
  arbvp::ExecInputs in = Inputs(1);
  size_t n = 0;
  for (auto _ : state) {
    auto program = Check(Variant(n++));
    benchmark::DoNotOptimize(arbvp::Interpret(*program, in));
  }
}
BENCHMARK(BM_RefNewProgram)->Unit(benchmark::kMicrosecond);

runtime::ArbExecutor* Mesa() {
  static std::unique_ptr<runtime::ArbExecutor> executor = [] {
    runtime::ExecOptions o;
    const char* driver = std::getenv("ARBITER_BENCH_DRIVER");
    const char* backend = std::getenv("ARBITER_BENCH_BACKEND");
    if (driver) o.driver = driver;
    if (backend && !runtime::ParseBackend(backend, &o.backend)) std::abort();
    std::string error;
    auto e = runtime::CreateArbExecutor(o, &error);
    if (!e) {
      std::fprintf(stderr, "exec_bench: %s\n", error.c_str());
      std::abort();
    }
    return e;
  }();
  return executor.get();
}

void BM_MesaVectors(benchmark::State& state) {
  Mesa();  // the context is made once, outside the timing
  auto program = Check(kLighting);
  arbvp::ExecInputs in = Inputs(static_cast<size_t>(state.range(0)));
  runtime::ArbPrograms programs{program.get(), nullptr};
  std::vector<arbvp::VectorResult> results;
  std::string error;
  for (auto _ : state) {
    if (!Mesa()->Run(programs, in, &results, &error)) state.SkipWithError(error.c_str());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_MesaVectors)->Arg(1)->Arg(1000)->Arg(4096)->Unit(benchmark::kMillisecond);

// A new program each iteration (compile + one vector): the per-program cost of verify.
void BM_MesaNewProgram(benchmark::State& state) {
  Mesa();
  arbvp::ExecInputs in = Inputs(1);
  std::vector<arbvp::VectorResult> results;
  std::string error;
  size_t n = 0;
  for (auto _ : state) {
    auto program = Check(Variant(n++));
    runtime::ArbPrograms programs{program.get(), nullptr};
    if (!Mesa()->Run(programs, in, &results, &error)) state.SkipWithError(error.c_str());
  }
}
BENCHMARK(BM_MesaNewProgram)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
