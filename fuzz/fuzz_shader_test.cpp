// Fuzz target: the .shader_test parser (piglit's shader_runner format) on any bytes.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "arbiter/runtime/shader_test.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace arbiter;
  if (size > fuzz::kMaxInputBytes) return -1;
  std::string_view text(reinterpret_cast<const char*>(data), size);
  runtime::ShaderTest test;
  int error_line = 0;
  std::string error;
  if (!runtime::ParseShaderTest(text, "fuzz.shader_test", &test, &error_line, &error)) {
    if (error.empty() || error_line < 0) __builtin_trap();
  }
  return 0;
}
