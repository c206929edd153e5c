// Fuzz target: the undefined-behaviour probe of `arbiter verify` for GLSL (glsl::FindHazards
// and the instrumented copy, runtime/src/glsl_verify/probe.cpp). Every shader arbiter's checker
// accepts as a program of one stage either has no probe, with a reason, or a probe that
// arbiter's checker accepts too, with a site for each hazard it wrapped; anything else is a
// bug of the instrumentation.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "arbiter/glsl/check.h"
#include "arbiter/glsl/reflect.h"
#include "fuzz_input.h"
#include "glsl_verify/internal.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace arbiter;
  if (size > fuzz::kMaxInputBytes) return -1;
  auto source = fuzz::MakeSource(data, size, "fuzz.glsl");
  for (glsl::Stage stage : {glsl::Stage::Vertex, glsl::Stage::Fragment}) {
    compiler::DiagnosticSink sink;
    const glsl::Reflection reflection = glsl::ReflectShader(stage, {source.get()}, &sink);
    if (!reflection.ok || sink.error_count() > 0) continue;
    runtime::GlslVerifySubject subject;
    subject.name = "fuzz";
    (stage == glsl::Stage::Vertex ? subject.vertex : subject.fragment) = source.get();
    (stage == glsl::Stage::Vertex ? subject.vertex_reflection : subject.fragment_reflection) =
        &reflection;
    const runtime::glsl_verify::Probe probe = runtime::glsl_verify::MakeProbe(subject);
    if (!probe.ok) {
      if (probe.why.empty()) __builtin_trap();
      continue;
    }
    const std::string& text = stage == glsl::Stage::Vertex ? probe.vertex : probe.fragment;
    compiler::SourceFile instrumented("probe.glsl", text);
    compiler::DiagnosticSink probe_sink;
    glsl::CheckOptions options;  // compiled as the original was (ReflectShader: no link)
    if (!glsl::CheckShader(stage, {&instrumented}, options, &probe_sink).ok) {
      std::fprintf(stderr, "shader:\n%s\nprobe:\n%s\n", source->text().c_str(), text.c_str());
      for (const compiler::Diagnostic& d : probe_sink.diagnostics()) {
        std::fprintf(stderr, "%s\n", d.message.c_str());
      }
      __builtin_trap();
    }
  }
  return 0;
}
