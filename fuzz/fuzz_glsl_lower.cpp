// Fuzz target: the lowering of GLSL 1.10/1.20 to Vulkan GLSL 4.50 (glsl/lower_vulkan.h). Every
// shader arbiter's checker accepts as a program of one stage is either refused with a reason or
// lowered to text that glslang compiles for Vulkan with the relaxed rules (with a main that
// calls arb_main); anything else is a bug of the lowering.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "arbiter/glsl/check.h"
#include "arbiter/glsl/lower_vulkan.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace arbiter;
  if (size > fuzz::kMaxInputBytes) return -1;
  auto source = fuzz::MakeSource(data, size, "fuzz.glsl");
  for (glsl::Stage stage : {glsl::Stage::Vertex, glsl::Stage::Fragment}) {
    compiler::DiagnosticSink sink;
    glsl::CheckOptions options;
    options.link = true;
    if (!glsl::CheckShader(stage, {source.get()}, options, &sink).ok) continue;
    const glsl::LoweredShader lowered = glsl::LowerForVulkan(stage, source->text());
    if (!lowered.not_applicable.empty()) {
      if (!lowered.text.empty() || !lowered.not_applicable.starts_with("not applicable: ")) {
        __builtin_trap();
      }
      continue;
    }
    const std::string text = lowered.text + "void main() { arb_main(); }\n";
    glsl::CompiledPair compiled;
    std::string error;
    const bool ok = stage == glsl::Stage::Vertex
                        ? glsl::CompileLoweredPair(text, "", &compiled, &error)
                        : glsl::CompileLoweredPair("", text, &compiled, &error);
    if (!ok) {
      std::fprintf(stderr, "shader:\n%s\nlowered:\n%s\nglslang: %s\n", source->text().c_str(),
                   text.c_str(), error.c_str());
      __builtin_trap();
    }
  }
  return 0;
}
