// Fuzz target: the GLSL check path (arbiter's directives, glslang compile and link, the
// strictness layer of 1.10 and 1.20, the extensions and EXT_gpu_shader4's 1.30 parse) on any
// bytes, as a vertex shader judged as a program and as a fragment shader object with a -D
// definition: the corpus files carry their stage in their name, which the fuzzer does not see.
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
    if (stage == glsl::Stage::Fragment) options.preprocessor.defines = {"FUZZ=1"};
    glsl::CheckResult result = glsl::CheckShader(stage, {source.get()}, options, &sink);
    if (result.ok != (sink.error_count() == 0)) __builtin_trap();
    for (const compiler::Diagnostic& d : sink.diagnostics()) {
      if (d.file != nullptr &&
          (d.range.begin > d.range.end || d.range.end > d.file->text().size())) {
        __builtin_trap();
      }
    }
  }
  return 0;
}
