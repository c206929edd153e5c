// Fuzz target: the reference interpreter on every program the checker accepts, over the
// edge vectors and a few random ones (the inputs `arbiter verify` draws).
#include <cstddef>
#include <cstdint>

#include "accept_arb.h"
#include "arbiter/arbvp/generate.h"
#include "arbiter/arbvp/interpret.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace arbiter;
  fuzz::AcceptedProgram accepted;
  // -1: not a corpus entry worth keeping.
  if (!fuzz::AcceptArbProgram(data, size, &accepted)) return -1;
  const arbvp::Program& program = *accepted.checked.program;
  const bool vertex = accepted.vertex;
  const compiler::SourceFile* source = accepted.source.get();
  arbvp::GenerateOptions options;
  options.random_vectors = 4;  // bounded: the edge batch already holds every special value
  options.seed = size;
  std::vector<arbvp::InputBatch> batches =
      arbvp::GenerateInputs(vertex ? &program : nullptr, vertex ? nullptr : &program, options);
  for (const arbvp::InputBatch& batch : batches) {
    std::vector<arbvp::VectorResult> results = arbvp::Interpret(program, batch.inputs, source);
    if (results.size() != batch.inputs.vectors.size()) __builtin_trap();
    if (!batch.inputs.vectors.empty()) {
      arbvp::DescribeReadInputs(vertex ? &program : nullptr, vertex ? nullptr : &program,
                                batch.inputs, 0);
    }
  }
  return 0;
}
