// What every fuzz target shares: the input-size cap and the bytes as a SourceFile.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "arbiter/arbvp/check.h"
#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/source.h"

namespace arbiter::fuzz {

// Larger inputs add no new paths, only time: a run must stay far below libFuzzer's timeout.
inline constexpr size_t kMaxInputBytes = 64 * 1024;

inline std::unique_ptr<compiler::SourceFile> MakeSource(const uint8_t* data, size_t size,
                                                        const char* path) {
  return std::make_unique<compiler::SourceFile>(
      path, std::string(reinterpret_cast<const char*>(data), size));
}

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
