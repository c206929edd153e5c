// Fuzz target: the GLSL check path (glslang compile and link plus arbiter's 1.10 strictness
// layer) on any bytes, as a vertex and as a fragment shader: the corpus files carry their
// stage in their name, which the fuzzer does not see.
#include <cstddef>
#include <cstdint>

#include "arbiter/glsl/check.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace arbiter;
  if (size > fuzz::kMaxInputBytes) return -1;
  auto source = fuzz::MakeSource(data, size, "fuzz.glsl");
  for (glsl::Stage stage : {glsl::Stage::Vertex, glsl::Stage::Fragment}) {
    compiler::DiagnosticSink sink;
    glsl::CheckOptions options;
    options.link = stage == glsl::Stage::Vertex;
    glsl::CheckResult result = glsl::CheckShader(stage, {source.get()}, options, &sink);
    if (result.ok != (sink.error_count() == 0)) __builtin_trap();
    for (const compiler::Diagnostic& d : sink.diagnostics()) {
      if (d.file == source.get() && (d.range.begin > d.range.end || d.range.end > size)) {
        __builtin_trap();
      }
    }
  }
  return 0;
}
