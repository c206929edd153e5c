// The ARB targets beyond the checker (interpreter, translator) start from an accepted program.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "arbiter/arbvp/check.h"
#include "arbiter/compiler/diagnostic.h"
#include "fuzz_input.h"

namespace arbiter::fuzz {

// An input the ARB checker accepts, for the targets that go further than the checker.
struct AcceptedProgram {
  std::unique_ptr<compiler::SourceFile> source;
  arbvp::CheckResult checked;
  bool vertex = false;
};

// The input as an accepted ARB program; false (input too large, or rejected) otherwise.
inline bool AcceptArbProgram(const uint8_t* data, size_t size, AcceptedProgram* out) {
  if (size > kMaxInputBytes) return false;
  out->source = MakeSource(data, size, "fuzz.arb");
  compiler::DiagnosticSink sink;
  out->checked = arbvp::CheckProgram(*out->source, arbvp::CheckOptions{}, &sink);
  if (!out->checked.ok || !out->checked.program) return false;
  out->vertex = out->checked.program->kind == arbvp::ProgramKind::Vertex;
  return true;
}

}  // namespace arbiter::fuzz
