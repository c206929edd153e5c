// Fuzz target: the ARB lexer, parser and checker (vertex and fragment programs) on any bytes,
// with the default limits (Mesa's), then with an error limit of 1 and the other kind expected.
#include <cstddef>
#include <cstdint>

#include "arbiter/arbvp/check.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace arbiter;
  if (size > fuzz::kMaxInputBytes) return -1;
  auto source = fuzz::MakeSource(data, size, "fuzz.arb");
  compiler::DiagnosticSink sink;
  arbvp::CheckResult result = arbvp::CheckProgram(*source, arbvp::CheckOptions{}, &sink);
  // The diagnostics' locations must lie inside the text (the renderers index with them).
  for (const compiler::Diagnostic& d : sink.diagnostics()) {
    if (d.file == source.get() && (d.range.begin > d.range.end || d.range.end > size)) {
      __builtin_trap();
    }
  }
  if (result.ok != (sink.error_count() == 0)) __builtin_trap();
  // A second pass with an error limit and the other kind expected exercises the paths that
  // stop early.
  compiler::DiagnosticSink limited(1);
  arbvp::CheckOptions options;
  options.expected_kind = result.program && result.program->kind == arbvp::ProgramKind::Vertex
                              ? arbvp::ProgramKind::Fragment
                              : arbvp::ProgramKind::Vertex;
  arbvp::CheckProgram(*source, options, &limited);
  return 0;
}
